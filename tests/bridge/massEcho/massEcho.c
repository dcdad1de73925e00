/* massEcho: a connector FMU for the bridge's tests of the optional mass
   inputs (docs/connector-fmu-interface.md). It declares the kinematic
   inputs A.r, A.R, B.r, B.R and the mass properties A.m, A.c[1..3],
   A.J[1..3,1..3] and the same for B, returns zero loads, and echoes every
   mass input in an output of the same name prefixed "echo." after each
   step, so that the connector's output file shows what the bridge fed.
   Value references: modelDescription.xml (written by build.py). */
#include "fmi2Functions.h"

#include <stdlib.h>
#include <string.h>

enum {
    massFirst = 24, /* A.m */
    nMass = 26, /* A.m, A.c, A.J, B.m, B.c, B.J */
    loadsFirst = 50, /* A.F, A.M, B.F, B.M */
    echoFirst = 62,
    nReal = 88
};

typedef struct {
    double r[nReal];
} Model;

static void echo(Model* m)
{
    memcpy(m->r + echoFirst, m->r + massFirst, nMass * sizeof(double));
}

const char* fmi2GetTypesPlatform(void)
{
    return fmi2TypesPlatform;
}
const char* fmi2GetVersion(void)
{
    return fmi2Version;
}
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean l, size_t n,
                               const fmi2String cat[])
{
    (void)c;
    (void)l;
    (void)n;
    (void)cat;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid,
                              fmi2String location,
                              const fmi2CallbackFunctions* f, fmi2Boolean v,
                              fmi2Boolean l)
{
    (void)name;
    (void)guid;
    (void)location;
    (void)f;
    (void)v;
    (void)l;
    if (type != fmi2CoSimulation)
        return NULL;
    Model* m = calloc(1, sizeof(Model));
    /* Identity orientations, unit masses until set */
    for (int i = 0; i < 3; ++i) {
        m->r[3 + 4 * i] = 1;
        m->r[15 + 4 * i] = 1;
    }
    m->r[24] = 1;
    m->r[37] = 1;
    echo(m);
    return m;
}
void fmi2FreeInstance(fmi2Component c)
{
    free(c);
}
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean a, fmi2Real b,
                               fmi2Real t0, fmi2Boolean d, fmi2Real e)
{
    (void)c;
    (void)a;
    (void)b;
    (void)t0;
    (void)d;
    (void)e;
    return fmi2OK;
}
fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    (void)c;
    return fmi2OK;
}
fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    echo(c);
    return fmi2OK;
}
fmi2Status fmi2Terminate(fmi2Component c)
{
    (void)c;
    return fmi2OK;
}
fmi2Status fmi2Reset(fmi2Component c)
{
    (void)c;
    return fmi2Error;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                       fmi2Real v[])
{
    Model* m = c;
    for (size_t i = 0; i < n; ++i) {
        if (vr[i] >= nReal)
            return fmi2Error;
        v[i] = m->r[vr[i]];
    }
    return fmi2OK;
}
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real v[])
{
    Model* m = c;
    for (size_t i = 0; i < n; ++i) {
        if (vr[i] >= loadsFirst)
            return fmi2Error;
        m->r[vr[i]] = v[i];
    }
    return fmi2OK;
}
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[],
                          size_t n, fmi2Integer v[])
{
    (void)c;
    (void)vr;
    (void)v;
    return n ? fmi2Error : fmi2OK;
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                          size_t n, fmi2Boolean v[])
{
    (void)c;
    (void)vr;
    (void)v;
    return n ? fmi2Error : fmi2OK;
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[],
                         size_t n, fmi2String v[])
{
    (void)c;
    (void)vr;
    (void)v;
    return n ? fmi2Error : fmi2OK;
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[],
                          size_t n, const fmi2Integer v[])
{
    (void)c;
    (void)vr;
    (void)v;
    return n ? fmi2Error : fmi2OK;
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                          size_t n, const fmi2Boolean v[])
{
    (void)c;
    (void)vr;
    (void)v;
    return n ? fmi2Error : fmi2OK;
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[],
                         size_t n, const fmi2String v[])
{
    (void)c;
    (void)vr;
    (void)v;
    return n ? fmi2Error : fmi2OK;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* s)
{
    if (!*s)
        *s = malloc(sizeof(Model));
    memcpy(*s, c, sizeof(Model));
    return fmi2OK;
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s)
{
    memcpy(c, s, sizeof(Model));
    return fmi2OK;
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* s)
{
    (void)c;
    free(*s);
    *s = NULL;
    return fmi2OK;
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s,
                                      size_t* n)
{
    (void)c;
    (void)s;
    *n = sizeof(Model);
    return fmi2OK;
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[],
                                 size_t n)
{
    (void)c;
    if (n != sizeof(Model))
        return fmi2Error;
    memcpy(b, s, n);
    return fmi2OK;
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[],
                                   size_t n, fmi2FMUstate* s)
{
    (void)c;
    if (n != sizeof(Model))
        return fmi2Error;
    if (!*s)
        *s = malloc(sizeof(Model));
    memcpy(*s, b, n);
    return fmi2OK;
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c,
                                        const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz,
                                        const fmi2Real dv[], fmi2Real dz[])
{
    (void)c;
    (void)u;
    (void)nu;
    (void)z;
    (void)nz;
    (void)dv;
    (void)dz;
    return fmi2Error;
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c,
                                       const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer o[],
                                       const fmi2Real v[])
{
    (void)c;
    (void)vr;
    (void)n;
    (void)o;
    (void)v;
    return fmi2Error;
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c,
                                        const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer o[], fmi2Real v[])
{
    (void)c;
    (void)vr;
    (void)n;
    (void)o;
    (void)v;
    return fmi2Error;
}
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean n)
{
    (void)t;
    (void)h;
    (void)n;
    echo(c);
    return fmi2OK;
}
fmi2Status fmi2CancelStep(fmi2Component c)
{
    (void)c;
    return fmi2Error;
}
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status* v)
{
    (void)c;
    (void)k;
    (void)v;
    return fmi2Discard;
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k,
                             fmi2Real* v)
{
    (void)c;
    (void)k;
    (void)v;
    return fmi2Discard;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k,
                                fmi2Integer* v)
{
    (void)c;
    (void)k;
    (void)v;
    return fmi2Discard;
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k,
                                fmi2Boolean* v)
{
    (void)c;
    (void)k;
    (void)v;
    return fmi2Discard;
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k,
                               fmi2String* v)
{
    (void)c;
    (void)k;
    (void)v;
    return fmi2Discard;
}

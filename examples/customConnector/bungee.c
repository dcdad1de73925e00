/* bungee: a connector FMU (FMI 2.0 co-simulation) for a line that only pulls.

   Law, between the attachment point P_A on body A and P_B on body B:

       p_A = A.r + A.R A.p,   p_B = B.r + B.R B.p        (global frame, m)
       d = p_B - p_A,  L = |d|,  e = L - restLength      (m)
       tension T = stiffness e + cubicStiffness e^3      (N) when e > 0
                 = 0                                     when slack (e <= 0)
       A.F = T d / L,  B.F = -A.F                        (N)
       A.M = (A.R A.p) x A.F,  B.M = (B.R B.p) x B.F     (N.m, about each
                                                          reference point)
       potentialEnergy = stiffness e^2 / 2 + cubicStiffness e^4 / 4 when e > 0

   At L = 0 the direction d / L is undefined; the line is then slack unless
   restLength is 0, and with e = 0 the tension is 0 too, so the loads are 0.

   Written against docs/connector-fmu-interface.md and the FMI 2.0 C API only
   (fmi2Functions.h), in C99. The variables below must match
   modelDescription.xml: value reference = position in the table. */

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

/* Must equal the guid attribute of modelDescription.xml */
#define BUNGEE_GUID "{6b1f0c7e-3d2a-4c59-9e41-b5a8d0f27c13}"

/* Value references */
enum {
    vrStiffness = 0,
    vrCubicStiffness = 1,
    vrRestLength = 2,
    vrAp = 3, /* A.p[1..3] */
    vrBp = 6, /* B.p[1..3] */
    vrAr = 9, /* A.r[1..3] */
    vrAR = 12, /* A.R[1,1], A.R[1,2], ..., A.R[3,3] */
    vrBr = 21,
    vrBR = 24,
    vrAF = 33,
    vrAM = 36,
    vrBF = 39,
    vrBM = 42,
    vrLength = 45,
    vrTension = 46,
    vrPotentialEnergy = 47,
    nVariables = 48
};

static const char* const variableNames[nVariables]
    = {"stiffness", "cubicStiffness", "restLength",     "A.p[1]",   "A.p[2]",
       "A.p[3]",    "B.p[1]",         "B.p[2]",         "B.p[3]",   "A.r[1]",
       "A.r[2]",    "A.r[3]",         "A.R[1,1]",       "A.R[1,2]", "A.R[1,3]",
       "A.R[2,1]",  "A.R[2,2]",       "A.R[2,3]",       "A.R[3,1]", "A.R[3,2]",
       "A.R[3,3]",  "B.r[1]",         "B.r[2]",         "B.r[3]",   "B.R[1,1]",
       "B.R[1,2]",  "B.R[1,3]",       "B.R[2,1]",       "B.R[2,2]", "B.R[2,3]",
       "B.R[3,1]",  "B.R[3,2]",       "B.R[3,3]",       "A.F[1]",   "A.F[2]",
       "A.F[3]",    "A.M[1]",         "A.M[2]",         "A.M[3]",   "B.F[1]",
       "B.F[2]",    "B.F[3]",         "B.M[1]",         "B.M[2]",   "B.M[3]",
       "length",    "tension",        "potentialEnergy"};

typedef enum {
    modeInstantiated,
    modeInitialization,
    modeStepping,
    modeTerminated
} Mode;

/* Everything that changes during a run: fmi2GetFMUstate copies it whole. */
typedef struct {
    Mode mode;
    double time; /* s, current communication point */
    int outputsCurrent; /* outputs evaluated from the current inputs */
    double v[nVariables]; /* every variable, by value reference */
} State;

typedef struct {
    fmi2CallbackLogger logger;
    fmi2ComponentEnvironment environment;
    char name[128];
    int loggingOn;
    State s;
} Instance;

/* Serialized state: this tag, then the State struct. */
static const char stateTag[8] = "bungee1";

static void logVa(const Instance* inst, fmi2Status status, const char* category,
                  const char* format, va_list args)
{
    char message[512];
    if (!inst->logger || (status == fmi2OK && !inst->loggingOn))
        return;
    vsnprintf(message, sizeof message, format, args);
    inst->logger(inst->environment, inst->name, status, category, "%s",
                 message);
}

/* Logs an error (category logStatusError) and returns fmi2Error. */
static fmi2Status fail(const Instance* inst, const char* format, ...)
{
    va_list args;
    va_start(args, format);
    logVa(inst, fmi2Error, "logStatusError", format, args);
    va_end(args);
    return fmi2Error;
}

static int isParameter(fmi2ValueReference vr)
{
    return vr < vrAr;
}
static int isInput(fmi2ValueReference vr)
{
    return vr >= vrAr && vr < vrAF;
}

static void setDefaults(State* s)
{
    memset(s, 0, sizeof *s);
    s->mode = modeInstantiated;
    s->v[vrStiffness] = 1000.0;
    s->v[vrRestLength] = 1.0;
    for (int i = 0; i < 3; ++i) {
        s->v[vrAR + 4 * i] = 1.0;
        s->v[vrBR + 4 * i] = 1.0;
    }
}

/* x = r + R p for body inputs at vrR (position), vrRot (orientation) */
static void attachment(const double* v, int vrR, int vrRot, int vrP,
                       double lever[3], double point[3])
{
    for (int i = 0; i < 3; ++i) {
        lever[i] = 0.0;
        for (int j = 0; j < 3; ++j)
            lever[i] += v[vrRot + 3 * i + j] * v[vrP + j];
        point[i] = v[vrR + i] + lever[i];
    }
}

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* The law: outputs from parameters and inputs. */
static fmi2Status evaluate(Instance* inst)
{
    double* v = inst->s.v;
    double leverA[3], leverB[3], pA[3], pB[3], d[3], FA[3], FB[3], MA[3], MB[3];
    attachment(v, vrAr, vrAR, vrAp, leverA, pA);
    attachment(v, vrBr, vrBR, vrBp, leverB, pB);
    for (int i = 0; i < 3; ++i)
        d[i] = pB[i] - pA[i];
    const double L = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double e = L - v[vrRestLength];
    const double k1 = v[vrStiffness], k3 = v[vrCubicStiffness];
    const double T = e > 0.0 ? k1 * e + k3 * e * e * e : 0.0;
    const double energy
        = e > 0.0 ? 0.5 * k1 * e * e + 0.25 * k3 * e * e * e * e : 0.0;
    if (!isfinite(T) || !isfinite(energy))
        return fail(
            inst,
            "at t = %g: stretch %g m gives a tension that is not finite: reduce stiffness %g N/m "
            "or cubicStiffness %g N/m3",
            inst->s.time, e, k1, k3);
    for (int i = 0; i < 3; ++i) {
        FA[i] = T > 0.0 ? T * d[i] / L : 0.0;
        FB[i] = -FA[i];
    }
    cross(leverA, FA, MA);
    cross(leverB, FB, MB);
    for (int i = 0; i < 3; ++i) {
        v[vrAF + i] = FA[i];
        v[vrAM + i] = MA[i];
        v[vrBF + i] = FB[i];
        v[vrBM + i] = MB[i];
    }
    v[vrLength] = L;
    v[vrTension] = T;
    v[vrPotentialEnergy] = energy;
    inst->s.outputsCurrent = 1;
    return fmi2OK;
}

/* Parameter ranges, checked when initialization ends. */
static fmi2Status checkParameters(Instance* inst)
{
    const double* v = inst->s.v;
    const struct {
        int vr;
        const char* unit;
    } ranges[] = {
        {vrStiffness, "N/m"}, {vrCubicStiffness, "N/m3"}, {vrRestLength, "m"}};
    for (size_t i = 0; i < sizeof ranges / sizeof ranges[0]; ++i)
        if (!(v[ranges[i].vr] >= 0.0))
            return fail(
                inst,
                "fmi2ExitInitializationMode: %s = %g %s is out of range: it must be >= 0",
                variableNames[ranges[i].vr], v[ranges[i].vr], ranges[i].unit);
    if (v[vrStiffness] == 0.0 && v[vrCubicStiffness] == 0.0)
        return fail(
            inst,
            "fmi2ExitInitializationMode: stiffness and cubicStiffness are both 0: "
            "the line would never pull; give either a value > 0");
    return fmi2OK;
}

/* ---------------------------------------------------------------- common */

const char* fmi2GetTypesPlatform(void)
{
    return fmi2TypesPlatform;
}
const char* fmi2GetVersion(void)
{
    return fmi2Version;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType,
                              fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions* functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn)
{
    (void)fmuResourceLocation;
    (void)visible;
    Instance probe;
    memset(&probe, 0, sizeof probe);
    if (functions) {
        probe.logger = functions->logger;
        probe.environment = functions->componentEnvironment;
    }
    snprintf(probe.name, sizeof probe.name, "%s",
             instanceName ? instanceName : "bungee");
    if (fmuType != fmi2CoSimulation) {
        (void)fail(
            &probe,
            "fmi2Instantiate: bungee is a co-simulation FMU only; model exchange is not supported");
        return NULL;
    }
    if (!fmuGUID || strcmp(fmuGUID, BUNGEE_GUID) != 0) {
        (void)fail(
            &probe,
            "fmi2Instantiate: GUID mismatch: modelDescription.xml has guid %s but bungee.so was built "
            "for %s; rebuild the binary and the XML together so that they carry the same GUID",
            fmuGUID ? fmuGUID : "(none)", BUNGEE_GUID);
        return NULL;
    }
    Instance* inst = calloc(1, sizeof *inst);
    if (!inst) {
        (void)fail(&probe, "fmi2Instantiate: out of memory");
        return NULL;
    }
    *inst = probe;
    inst->loggingOn = loggingOn != fmi2False;
    setDefaults(&inst->s);
    return inst;
}

void fmi2FreeInstance(fmi2Component c)
{
    free(c);
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn,
                               size_t nCategories,
                               const fmi2String categories[])
{
    (void)nCategories;
    (void)categories;
    ((Instance*)c)->loggingOn = loggingOn != fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    Instance* inst = c;
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    if (inst->s.mode != modeInstantiated)
        return fail(
            inst,
            "fmi2SetupExperiment: only allowed right after fmi2Instantiate or fmi2Reset");
    inst->s.time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    Instance* inst = c;
    if (inst->s.mode != modeInstantiated)
        return fail(
            inst,
            "fmi2EnterInitializationMode: only allowed after fmi2Instantiate or fmi2Reset");
    inst->s.mode = modeInitialization;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    Instance* inst = c;
    if (inst->s.mode != modeInitialization)
        return fail(inst,
                    "fmi2ExitInitializationMode: not in initialization mode");
    if (checkParameters(inst) != fmi2OK || evaluate(inst) != fmi2OK)
        return fmi2Error;
    inst->s.mode = modeStepping;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    ((Instance*)c)->s.mode = modeTerminated;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c)
{
    setDefaults(&((Instance*)c)->s);
    return fmi2OK;
}

/* ------------------------------------------------------------- variables */

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[],
                       size_t nvr, fmi2Real value[])
{
    Instance* inst = c;
    for (size_t i = 0; i < nvr; ++i) {
        if (vr[i] >= nVariables)
            return fail(inst, "fmi2GetReal: unknown value reference %u", vr[i]);
        if (vr[i] >= vrAF && !inst->s.outputsCurrent
            && evaluate(inst) != fmi2OK)
            return fmi2Error;
        value[i] = inst->s.v[vr[i]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[],
                       size_t nvr, const fmi2Real value[])
{
    Instance* inst = c;
    for (size_t i = 0; i < nvr; ++i) {
        if (vr[i] >= nVariables)
            return fail(inst, "fmi2SetReal: unknown value reference %u", vr[i]);
        const char* name = variableNames[vr[i]];
        if (!isParameter(vr[i]) && !isInput(vr[i]))
            return fail(inst, "fmi2SetReal: %s is an output and cannot be set",
                        name);
        if (isParameter(vr[i]) && inst->s.mode != modeInstantiated
            && inst->s.mode != modeInitialization)
            return fail(
                inst,
                "fmi2SetReal: %s is a fixed parameter: set it before fmi2ExitInitializationMode",
                name);
        if (!isfinite(value[i]))
            return fail(inst, "fmi2SetReal: %s = %g is not finite", name,
                        value[i]);
        inst->s.v[vr[i]] = value[i];
        inst->s.outputsCurrent = 0;
    }
    return fmi2OK;
}

static fmi2Status noSuchVariables(fmi2Component c, const char* function,
                                  size_t nvr, const fmi2ValueReference vr[])
{
    if (nvr == 0)
        return fmi2OK;
    return fail(
        (Instance*)c,
        "%s: unknown value reference %u: bungee has Real variables only",
        function, vr[0]);
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[],
                          size_t nvr, fmi2Integer value[])
{
    (void)value;
    return noSuchVariables(c, "fmi2GetInteger", nvr, vr);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                          size_t nvr, fmi2Boolean value[])
{
    (void)value;
    return noSuchVariables(c, "fmi2GetBoolean", nvr, vr);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[],
                         size_t nvr, fmi2String value[])
{
    (void)value;
    return noSuchVariables(c, "fmi2GetString", nvr, vr);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[],
                          size_t nvr, const fmi2Integer value[])
{
    (void)value;
    return noSuchVariables(c, "fmi2SetInteger", nvr, vr);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                          size_t nvr, const fmi2Boolean value[])
{
    (void)value;
    return noSuchVariables(c, "fmi2SetBoolean", nvr, vr);
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[],
                         size_t nvr, const fmi2String value[])
{
    (void)value;
    return noSuchVariables(c, "fmi2SetString", nvr, vr);
}

/* ------------------------------------------------------------- FMU state */

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate)
{
    Instance* inst = c;
    State* copy = *FMUstate ? *FMUstate : malloc(sizeof *copy);
    if (!copy)
        return fail(inst, "fmi2GetFMUstate: out of memory");
    *copy = inst->s;
    *FMUstate = copy;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    Instance* inst = c;
    if (!FMUstate)
        return fail(inst, "fmi2SetFMUstate: no state given");
    inst->s = *(const State*)FMUstate;
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate)
{
    (void)c;
    if (FMUstate) {
        free(*FMUstate);
        *FMUstate = NULL;
    }
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate,
                                      size_t* size)
{
    (void)c;
    (void)FMUstate;
    *size = sizeof stateTag + sizeof(State);
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                 fmi2Byte serializedState[], size_t size)
{
    Instance* inst = c;
    if (!FMUstate || size != sizeof stateTag + sizeof(State))
        return fail(
            inst,
            "fmi2SerializeFMUstate: needs a state and a buffer of %zu bytes, got %zu",
            sizeof stateTag + sizeof(State), size);
    memcpy(serializedState, stateTag, sizeof stateTag);
    memcpy(serializedState + sizeof stateTag, FMUstate, sizeof(State));
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c,
                                   const fmi2Byte serializedState[],
                                   size_t size, fmi2FMUstate* FMUstate)
{
    Instance* inst = c;
    if (size != sizeof stateTag + sizeof(State)
        || memcmp(serializedState, stateTag, sizeof stateTag) != 0)
        return fail(
            inst,
            "fmi2DeSerializeFMUstate: %zu bytes that are not a state of this bungee.so "
            "(expected %zu bytes starting with '%s')",
            size, sizeof stateTag + sizeof(State), stateTag);
    State* copy = *FMUstate ? *FMUstate : malloc(sizeof *copy);
    if (!copy)
        return fail(inst, "fmi2DeSerializeFMUstate: out of memory");
    memcpy(copy, serializedState + sizeof stateTag, sizeof(State));
    *FMUstate = copy;
    return fmi2OK;
}

/* ---------------------------------------------------------- co-simulation */

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    Instance* inst = c;
    (void)noSetFMUStatePriorToCurrentPoint;
    if (inst->s.mode != modeStepping)
        return fail(
            inst,
            "fmi2DoStep: call fmi2ExitInitializationMode first (or the FMU is terminated)");
    if (!(communicationStepSize >= 0.0) || !isfinite(currentCommunicationPoint))
        return fail(
            inst,
            "fmi2DoStep: step from t = %g by %g s: the step size must be >= 0",
            currentCommunicationPoint, communicationStepSize);
    /* No internal dynamics: the loads follow the inputs at t + h. */
    inst->s.time = currentCommunicationPoint + communicationStepSize;
    return evaluate(inst);
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    return fail(
        (Instance*)c,
        "fmi2CancelStep: bungee steps synchronously; there is nothing to cancel");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s,
                         fmi2Status* value)
{
    (void)s;
    (void)value;
    return fail(
        (Instance*)c,
        "fmi2GetStatus: bungee steps synchronously; no status to ask for");
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s,
                             fmi2Real* value)
{
    if (s != fmi2LastSuccessfulTime)
        return fail(
            (Instance*)c,
            "fmi2GetRealStatus: only fmi2LastSuccessfulTime is available");
    *value = ((Instance*)c)->s.time;
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s,
                                fmi2Integer* value)
{
    (void)s;
    (void)value;
    return fail((Instance*)c, "fmi2GetIntegerStatus: no integer status");
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s,
                                fmi2Boolean* value)
{
    if (s != fmi2Terminated)
        return fail((Instance*)c,
                    "fmi2GetBooleanStatus: only fmi2Terminated is available");
    *value = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s,
                               fmi2String* value)
{
    (void)s;
    (void)value;
    return fail((Instance*)c, "fmi2GetStringStatus: no string status");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c,
                                       const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[])
{
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    return fail(
        (Instance*)c,
        "fmi2SetRealInputDerivatives: not supported (canInterpolateInputs=\"false\")");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c,
                                        const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[],
                                        fmi2Real value[])
{
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    return fail(
        (Instance*)c,
        "fmi2GetRealOutputDerivatives: not supported (maxOutputDerivativeOrder=\"0\")");
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c,
                                        const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[])
{
    (void)vUnknown_ref;
    (void)nUnknown;
    (void)vKnown_ref;
    (void)nKnown;
    (void)dvKnown;
    (void)dvUnknown;
    return fail(
        (Instance*)c,
        "fmi2GetDirectionalDerivative: not supported (providesDirectionalDerivative=\"false\")");
}

/* ------------------------------------------- model exchange: not provided */

#define NO_MODEL_EXCHANGE(function)                                            \
    fail((Instance*)c,                                                         \
         "%s: bungee is a co-simulation FMU; model exchange is not supported", \
         function)

fmi2Status fmi2EnterEventMode(fmi2Component c)
{
    return NO_MODEL_EXCHANGE("fmi2EnterEventMode");
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo* eventInfo)
{
    (void)eventInfo;
    return NO_MODEL_EXCHANGE("fmi2NewDiscreteStates");
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c)
{
    return NO_MODEL_EXCHANGE("fmi2EnterContinuousTimeMode");
}

fmi2Status fmi2CompletedIntegratorStep(
    fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
    fmi2Boolean* enterEventMode, fmi2Boolean* terminateSimulation)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    (void)enterEventMode;
    (void)terminateSimulation;
    return NO_MODEL_EXCHANGE("fmi2CompletedIntegratorStep");
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time)
{
    (void)time;
    return NO_MODEL_EXCHANGE("fmi2SetTime");
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[],
                                   size_t nx)
{
    (void)x;
    (void)nx;
    return NO_MODEL_EXCHANGE("fmi2SetContinuousStates");
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[],
                              size_t nx)
{
    (void)derivatives;
    (void)nx;
    return NO_MODEL_EXCHANGE("fmi2GetDerivatives");
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[],
                                  size_t ni)
{
    (void)eventIndicators;
    (void)ni;
    return NO_MODEL_EXCHANGE("fmi2GetEventIndicators");
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx)
{
    (void)x;
    (void)nx;
    return NO_MODEL_EXCHANGE("fmi2GetContinuousStates");
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c,
                                             fmi2Real x_nominal[], size_t nx)
{
    (void)x_nominal;
    (void)nx;
    return NO_MODEL_EXCHANGE("fmi2GetNominalsOfContinuousStates");
}

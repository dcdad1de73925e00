/* bungee3: the bungee connector (bungee.c) as an FMI 3.0 co-simulation FMU.

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

   Written against docs/connector-fmu-interface.md ("FMI 3.0") and the FMI
   3.0 C API only (fmi3Functions.h), in C99. Vectors and matrices are
   Float64 arrays: A.p, B.p, A.r, B.r, A.F, A.M, B.F, B.M of 3 elements,
   A.R and B.R of 3 x 3, row-major (A.R[i,j] is element 3 (i - 1) + j).
   The variables below must match fmi3/modelDescription.xml: an array's
   value reference is the index of its first element in State.v, and its
   other elements have no value reference. */

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"

/* Must equal the instantiationToken of fmi3/modelDescription.xml */
#define BUNGEE3_TOKEN "{d41c7a55-2f0e-4b8a-9c36-7e19a4b2f5d8}"

/* Value references = offsets of the variables' first elements in State.v */
enum {
    vrStiffness = 0,
    vrCubicStiffness = 1,
    vrRestLength = 2,
    vrAp = 3, /* A.p, 3 */
    vrBp = 6, /* B.p, 3 */
    vrAr = 9, /* A.r, 3 */
    vrAR = 12, /* A.R, 3 x 3 row-major */
    vrBr = 21,
    vrBR = 24,
    vrAF = 33,
    vrAM = 36,
    vrBF = 39,
    vrBM = 42,
    vrLength = 45,
    vrTension = 46,
    vrPotentialEnergy = 47,
    nElements = 48
};

typedef enum { parameter, input, output } Causality;

typedef struct {
    const char* name;
    fmi3ValueReference vr;
    size_t rows, columns; /* 1 x 1: scalar; n x 1: vector; 3 x 3: matrix */
    Causality causality;
} Variable;

static const Variable variables[]
    = {{"stiffness", vrStiffness, 1, 1, parameter},
       {"cubicStiffness", vrCubicStiffness, 1, 1, parameter},
       {"restLength", vrRestLength, 1, 1, parameter},
       {"A.p", vrAp, 3, 1, parameter},
       {"B.p", vrBp, 3, 1, parameter},
       {"A.r", vrAr, 3, 1, input},
       {"A.R", vrAR, 3, 3, input},
       {"B.r", vrBr, 3, 1, input},
       {"B.R", vrBR, 3, 3, input},
       {"A.F", vrAF, 3, 1, output},
       {"A.M", vrAM, 3, 1, output},
       {"B.F", vrBF, 3, 1, output},
       {"B.M", vrBM, 3, 1, output},
       {"length", vrLength, 1, 1, output},
       {"tension", vrTension, 1, 1, output},
       {"potentialEnergy", vrPotentialEnergy, 1, 1, output}};

enum { nVariables = sizeof variables / sizeof variables[0] };

typedef enum {
    modeInstantiated,
    modeInitialization,
    modeStepping,
    modeTerminated
} Mode;

/* Everything that changes during a run: fmi3GetFMUState copies it whole. */
typedef struct {
    Mode mode;
    double time; /* s, current communication point */
    int outputsCurrent; /* outputs evaluated from the current inputs */
    double v[nElements]; /* every element of every variable */
} State;

typedef struct {
    fmi3LogMessageCallback logger;
    fmi3InstanceEnvironment environment;
    char name[128];
    int loggingOn;
    State s;
} Instance;

/* Serialized state: this tag, then the State struct. */
static const char stateTag[8] = "bungee3";

static void logVa(const Instance* inst, fmi3Status status, const char* category,
                  const char* format, va_list args)
{
    char message[512];
    if (!inst->logger || (status == fmi3OK && !inst->loggingOn))
        return;
    vsnprintf(message, sizeof message, format, args);
    inst->logger(inst->environment, status, category, message);
}

/* Logs an error (category logStatusError) and returns fmi3Error. */
static fmi3Status fail(const Instance* inst, const char* format, ...)
{
    va_list args;
    va_start(args, format);
    logVa(inst, fmi3Error, "logStatusError", format, args);
    va_end(args);
    return fmi3Error;
}

static const Variable* findVariable(fmi3ValueReference vr)
{
    for (size_t i = 0; i < nVariables; ++i)
        if (variables[i].vr == vr)
            return &variables[i];
    return NULL;
}

/* "A.R[1,2]", "A.r[3]" or "stiffness": element k of the variable */
static void elementName(const Variable* var, size_t k, char* name, size_t size)
{
    if (var->rows * var->columns == 1)
        snprintf(name, size, "%s", var->name);
    else if (var->columns == 1)
        snprintf(name, size, "%s[%zu]", var->name, k + 1);
    else
        snprintf(name, size, "%s[%zu,%zu]", var->name, k / var->columns + 1,
                 k % var->columns + 1);
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
static fmi3Status evaluate(Instance* inst)
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
    memcpy(v + vrAF, FA, sizeof FA);
    memcpy(v + vrAM, MA, sizeof MA);
    memcpy(v + vrBF, FB, sizeof FB);
    memcpy(v + vrBM, MB, sizeof MB);
    v[vrLength] = L;
    v[vrTension] = T;
    v[vrPotentialEnergy] = energy;
    inst->s.outputsCurrent = 1;
    return fmi3OK;
}

/* Parameter ranges, checked when initialization ends. */
static fmi3Status checkParameters(Instance* inst)
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
                "fmi3ExitInitializationMode: %s = %g %s is out of range: it must be >= 0",
                findVariable(ranges[i].vr)->name, v[ranges[i].vr],
                ranges[i].unit);
    if (v[vrStiffness] == 0.0 && v[vrCubicStiffness] == 0.0)
        return fail(
            inst,
            "fmi3ExitInitializationMode: stiffness and cubicStiffness are both 0: "
            "the line would never pull; give either a value > 0");
    return fmi3OK;
}

/* ---------------------------------------------------------- instances */

const char* fmi3GetVersion(void)
{
    return fmi3Version;
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
                               size_t nCategories,
                               const fmi3String categories[])
{
    (void)nCategories;
    (void)categories;
    ((Instance*)instance)->loggingOn = loggingOn != fmi3False;
    return fmi3OK;
}

/* An instance that only logs, for the refusals of fmi3Instantiate* */
static Instance probe(fmi3String instanceName, fmi3InstanceEnvironment env,
                      fmi3LogMessageCallback logger)
{
    Instance inst;
    memset(&inst, 0, sizeof inst);
    inst.logger = logger;
    inst.environment = env;
    snprintf(inst.name, sizeof inst.name, "%s",
             instanceName ? instanceName : "bungee3");
    return inst;
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken,
    fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
    fmi3Boolean eventModeUsed, fmi3Boolean earlyReturnAllowed,
    const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables,
    fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage,
    fmi3IntermediateUpdateCallback intermediateUpdate)
{
    (void)resourcePath;
    (void)visible;
    (void)earlyReturnAllowed; /* it never returns early */
    (void)requiredIntermediateVariables;
    (void)nRequiredIntermediateVariables;
    (void)intermediateUpdate;
    Instance p = probe(instanceName, instanceEnvironment, logMessage);
    if (eventModeUsed) {
        (void)fail(
            &p,
            "fmi3InstantiateCoSimulation: bungee3 has no event mode (hasEventMode=\"false\"); "
            "instantiate it with eventModeUsed false");
        return NULL;
    }
    if (!instantiationToken || strcmp(instantiationToken, BUNGEE3_TOKEN) != 0) {
        (void)fail(
            &p,
            "fmi3InstantiateCoSimulation: instantiationToken mismatch: modelDescription.xml has %s "
            "but bungee3.so was built for %s; rebuild the binary and the XML together so that "
            "they carry the same token",
            instantiationToken ? instantiationToken : "(none)", BUNGEE3_TOKEN);
        return NULL;
    }
    Instance* inst = calloc(1, sizeof *inst);
    if (!inst) {
        (void)fail(&p, "fmi3InstantiateCoSimulation: out of memory");
        return NULL;
    }
    *inst = p;
    inst->loggingOn = loggingOn != fmi3False;
    setDefaults(&inst->s);
    return inst;
}

fmi3Instance fmi3InstantiateModelExchange(
    fmi3String instanceName, fmi3String instantiationToken,
    fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
    fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage)
{
    (void)instantiationToken;
    (void)resourcePath;
    (void)visible;
    (void)loggingOn;
    Instance p = probe(instanceName, instanceEnvironment, logMessage);
    (void)fail(
        &p,
        "fmi3InstantiateModelExchange: bungee3 is a co-simulation FMU only");
    return NULL;
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken,
    fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
    fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption,
    fmi3UnlockPreemptionCallback unlockPreemption)
{
    (void)instantiationToken;
    (void)resourcePath;
    (void)visible;
    (void)loggingOn;
    (void)clockUpdate;
    (void)lockPreemption;
    (void)unlockPreemption;
    Instance p = probe(instanceName, instanceEnvironment, logMessage);
    (void)fail(
        &p,
        "fmi3InstantiateScheduledExecution: bungee3 is a co-simulation FMU only");
    return NULL;
}

void fmi3FreeInstance(fmi3Instance instance)
{
    free(instance);
}

fmi3Status
fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined,
                            fmi3Float64 tolerance, fmi3Float64 startTime,
                            fmi3Boolean stopTimeDefined, fmi3Float64 stopTime)
{
    Instance* inst = instance;
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    if (inst->s.mode != modeInstantiated)
        return fail(
            inst,
            "fmi3EnterInitializationMode: only allowed after fmi3InstantiateCoSimulation or fmi3Reset");
    inst->s.time = startTime;
    inst->s.mode = modeInitialization;
    return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance)
{
    Instance* inst = instance;
    if (inst->s.mode != modeInitialization)
        return fail(inst,
                    "fmi3ExitInitializationMode: not in initialization mode");
    if (checkParameters(inst) != fmi3OK || evaluate(inst) != fmi3OK)
        return fmi3Error;
    inst->s.mode = modeStepping; /* no event mode: straight to step mode */
    return fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance instance)
{
    ((Instance*)instance)->s.mode = modeTerminated;
    return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance instance)
{
    setDefaults(&((Instance*)instance)->s);
    return fmi3OK;
}

/* ---------------------------------------------------------- variables */

/* Checks that vr[0..nvr) are variables whose elements number nValues;
   fmi3Error, logged, for an unknown value reference or another count. */
static fmi3Status checkValueReferences(Instance* inst, const char* function,
                                       const fmi3ValueReference vr[],
                                       size_t nvr, size_t nValues)
{
    size_t elements = 0;
    for (size_t i = 0; i < nvr; ++i) {
        const Variable* var = findVariable(vr[i]);
        if (!var)
            return fail(
                inst,
                "%s: unknown value reference %u: an array has the value reference of its first "
                "element only",
                function, vr[i]);
        elements += var->rows * var->columns;
    }
    if (elements != nValues)
        return fail(
            inst,
            "%s: nValues = %zu but the value references given have %zu elements",
            function, nValues, elements);
    return fmi3OK;
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[],
                          size_t nvr, fmi3Float64 values[], size_t nValues)
{
    Instance* inst = instance;
    if (checkValueReferences(inst, "fmi3GetFloat64", vr, nvr, nValues)
        != fmi3OK)
        return fmi3Error;
    for (size_t i = 0; i < nvr; ++i) {
        const Variable* var = findVariable(vr[i]);
        const size_t n = var->rows * var->columns;
        if (var->causality == output && !inst->s.outputsCurrent
            && evaluate(inst) != fmi3OK)
            return fmi3Error;
        memcpy(values, inst->s.v + var->vr, n * sizeof *values);
        values += n;
    }
    return fmi3OK;
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[],
                          size_t nvr, const fmi3Float64 values[],
                          size_t nValues)
{
    Instance* inst = instance;
    if (checkValueReferences(inst, "fmi3SetFloat64", vr, nvr, nValues)
        != fmi3OK)
        return fmi3Error;
    for (size_t i = 0; i < nvr; ++i) {
        const Variable* var = findVariable(vr[i]);
        if (var->causality == output)
            return fail(inst,
                        "fmi3SetFloat64: %s is an output and cannot be set",
                        var->name);
        if (var->causality == parameter && inst->s.mode != modeInstantiated
            && inst->s.mode != modeInitialization)
            return fail(
                inst,
                "fmi3SetFloat64: %s is a fixed parameter: set it before fmi3ExitInitializationMode",
                var->name);
        const size_t n = var->rows * var->columns;
        for (size_t k = 0; k < n; ++k) {
            if (!isfinite(values[k])) {
                char name[64];
                elementName(var, k, name, sizeof name);
                return fail(inst, "fmi3SetFloat64: %s = %g is not finite", name,
                            values[k]);
            }
            inst->s.v[var->vr + k] = values[k];
        }
        values += n;
        inst->s.outputsCurrent = 0;
    }
    return fmi3OK;
}

static fmi3Status noSuchVariables(fmi3Instance instance, const char* function,
                                  size_t nvr, const fmi3ValueReference vr[])
{
    if (nvr == 0)
        return fmi3OK;
    return fail(
        (Instance*)instance,
        "%s: unknown value reference %u: bungee3 has Float64 variables only",
        function, vr[0]);
}

/* fmi3Get<Type> and fmi3Set<Type> of a type bungee3 has no variables of */
#define NO_VARIABLES_OF_TYPE(function, valueType)                              \
    fmi3Status function(fmi3Instance instance, const fmi3ValueReference vr[],  \
                        size_t nvr, valueType values[], size_t nValues)        \
    {                                                                          \
        (void)values;                                                          \
        (void)nValues;                                                         \
        return noSuchVariables(instance, #function, nvr, vr);                  \
    }

NO_VARIABLES_OF_TYPE(fmi3GetFloat32, fmi3Float32)
NO_VARIABLES_OF_TYPE(fmi3GetInt8, fmi3Int8)
NO_VARIABLES_OF_TYPE(fmi3GetUInt8, fmi3UInt8)
NO_VARIABLES_OF_TYPE(fmi3GetInt16, fmi3Int16)
NO_VARIABLES_OF_TYPE(fmi3GetUInt16, fmi3UInt16)
NO_VARIABLES_OF_TYPE(fmi3GetInt32, fmi3Int32)
NO_VARIABLES_OF_TYPE(fmi3GetUInt32, fmi3UInt32)
NO_VARIABLES_OF_TYPE(fmi3GetInt64, fmi3Int64)
NO_VARIABLES_OF_TYPE(fmi3GetUInt64, fmi3UInt64)
NO_VARIABLES_OF_TYPE(fmi3GetBoolean, fmi3Boolean)
NO_VARIABLES_OF_TYPE(fmi3GetString, fmi3String)
NO_VARIABLES_OF_TYPE(fmi3SetFloat32, const fmi3Float32)
NO_VARIABLES_OF_TYPE(fmi3SetInt8, const fmi3Int8)
NO_VARIABLES_OF_TYPE(fmi3SetUInt8, const fmi3UInt8)
NO_VARIABLES_OF_TYPE(fmi3SetInt16, const fmi3Int16)
NO_VARIABLES_OF_TYPE(fmi3SetUInt16, const fmi3UInt16)
NO_VARIABLES_OF_TYPE(fmi3SetInt32, const fmi3Int32)
NO_VARIABLES_OF_TYPE(fmi3SetUInt32, const fmi3UInt32)
NO_VARIABLES_OF_TYPE(fmi3SetInt64, const fmi3Int64)
NO_VARIABLES_OF_TYPE(fmi3SetUInt64, const fmi3UInt64)
NO_VARIABLES_OF_TYPE(fmi3SetBoolean, const fmi3Boolean)
NO_VARIABLES_OF_TYPE(fmi3SetString, const fmi3String)

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[],
                         size_t nvr, size_t valueSizes[], fmi3Binary values[],
                         size_t nValues)
{
    (void)valueSizes;
    (void)values;
    (void)nValues;
    return noSuchVariables(instance, "fmi3GetBinary", nvr, vr);
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[],
                         size_t nvr, const size_t valueSizes[],
                         const fmi3Binary values[], size_t nValues)
{
    (void)valueSizes;
    (void)values;
    (void)nValues;
    return noSuchVariables(instance, "fmi3SetBinary", nvr, vr);
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference vr[],
                        size_t nvr, fmi3Clock values[])
{
    (void)values;
    return noSuchVariables(instance, "fmi3GetClock", nvr, vr);
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference vr[],
                        size_t nvr, const fmi3Clock values[])
{
    (void)values;
    return noSuchVariables(instance, "fmi3SetClock", nvr, vr);
}

/* ---------------------------------------------------------- FMU state */

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState)
{
    Instance* inst = instance;
    State* copy = *FMUState ? *FMUState : malloc(sizeof *copy);
    if (!copy)
        return fail(inst, "fmi3GetFMUState: out of memory");
    *copy = inst->s;
    *FMUState = copy;
    return fmi3OK;
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState)
{
    Instance* inst = instance;
    if (!FMUState)
        return fail(inst, "fmi3SetFMUState: no state given");
    inst->s = *(const State*)FMUState;
    return fmi3OK;
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState)
{
    (void)instance;
    if (FMUState) {
        free(*FMUState);
        *FMUState = NULL;
    }
    return fmi3OK;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance,
                                      fmi3FMUState FMUState, size_t* size)
{
    (void)instance;
    (void)FMUState;
    *size = sizeof stateTag + sizeof(State);
    return fmi3OK;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                 fmi3Byte serializedState[], size_t size)
{
    Instance* inst = instance;
    if (!FMUState || size != sizeof stateTag + sizeof(State))
        return fail(
            inst,
            "fmi3SerializeFMUState: needs a state and a buffer of %zu bytes, got %zu",
            sizeof stateTag + sizeof(State), size);
    memcpy(serializedState, stateTag, sizeof stateTag);
    memcpy(serializedState + sizeof stateTag, FMUState, sizeof(State));
    return fmi3OK;
}

/* Always a new state (FMI 3.0): *FMUState is not read */
fmi3Status fmi3DeserializeFMUState(fmi3Instance instance,
                                   const fmi3Byte serializedState[],
                                   size_t size, fmi3FMUState* FMUState)
{
    Instance* inst = instance;
    if (size != sizeof stateTag + sizeof(State)
        || memcmp(serializedState, stateTag, sizeof stateTag) != 0)
        return fail(
            inst,
            "fmi3DeserializeFMUState: %zu bytes that are not a state of this bungee3.so "
            "(expected %zu bytes starting with '%s')",
            size, sizeof stateTag + sizeof(State), stateTag);
    State* copy = malloc(sizeof *copy);
    if (!copy)
        return fail(inst, "fmi3DeserializeFMUState: out of memory");
    memcpy(copy, serializedState + sizeof stateTag, sizeof(State));
    *FMUState = copy;
    return fmi3OK;
}

/* ------------------------------------------------------- co-simulation */

fmi3Status fmi3DoStep(fmi3Instance instance,
                      fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean* eventHandlingNeeded,
                      fmi3Boolean* terminateSimulation,
                      fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime)
{
    Instance* inst = instance;
    (void)noSetFMUStatePriorToCurrentPoint;
    *eventHandlingNeeded = fmi3False;
    *terminateSimulation = fmi3False;
    *earlyReturn = fmi3False;
    *lastSuccessfulTime = inst->s.time;
    if (inst->s.mode != modeStepping)
        return fail(
            inst,
            "fmi3DoStep: call fmi3ExitInitializationMode first (or the FMU is terminated)");
    if (!(communicationStepSize >= 0.0) || !isfinite(currentCommunicationPoint))
        return fail(
            inst,
            "fmi3DoStep: step from t = %g by %g s: the step size must be >= 0",
            currentCommunicationPoint, communicationStepSize);
    /* No internal dynamics: the loads follow the inputs at t + h. */
    inst->s.time = currentCommunicationPoint + communicationStepSize;
    *lastSuccessfulTime = inst->s.time;
    return evaluate(inst);
}

/* ------------------------------- functions that do not apply: fmi3Error */

#define NOT_PROVIDED(function, reason)                                         \
    fail((Instance*)instance, "%s: %s", function, reason)

static const char noEventMode[]
    = "bungee3 has no event mode (hasEventMode=\"false\")";

fmi3Status fmi3EnterEventMode(fmi3Instance instance)
{
    return NOT_PROVIDED("fmi3EnterEventMode", noEventMode);
}

fmi3Status fmi3EnterStepMode(fmi3Instance instance)
{
    return NOT_PROVIDED("fmi3EnterStepMode", noEventMode);
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance,
                                    fmi3Boolean* discreteStatesNeedUpdate,
                                    fmi3Boolean* terminateSimulation,
                                    fmi3Boolean* nominalsChanged,
                                    fmi3Boolean* valuesChanged,
                                    fmi3Boolean* nextEventTimeDefined,
                                    fmi3Float64* nextEventTime)
{
    (void)discreteStatesNeedUpdate;
    (void)terminateSimulation;
    (void)nominalsChanged;
    (void)valuesChanged;
    (void)nextEventTimeDefined;
    (void)nextEventTime;
    return NOT_PROVIDED("fmi3UpdateDiscreteStates", noEventMode);
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
{
    return NOT_PROVIDED("fmi3EvaluateDiscreteStates",
                        "bungee3 has no discrete states");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance)
{
    return NOT_PROVIDED("fmi3EnterConfigurationMode",
                        "bungee3 has no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance)
{
    return NOT_PROVIDED("fmi3ExitConfigurationMode",
                        "bungee3 has no structural parameters");
}

fmi3Status
fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                    fmi3ValueReference valueReference,
                                    size_t* nDependencies)
{
    (void)valueReference;
    (void)nDependencies;
    return NOT_PROVIDED(
        "fmi3GetNumberOfVariableDependencies",
        "not provided; modelDescription.xml lists the dependencies");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance,
                                       fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[],
                                       fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[],
                                       fmi3DependencyKind dependencyKinds[],
                                       size_t nDependencies)
{
    (void)dependent;
    (void)elementIndicesOfDependent;
    (void)independents;
    (void)elementIndicesOfIndependents;
    (void)dependencyKinds;
    (void)nDependencies;
    return NOT_PROVIDED(
        "fmi3GetVariableDependencies",
        "not provided; modelDescription.xml lists the dependencies");
}

/* fmi3GetDirectionalDerivative and fmi3GetAdjointDerivative */
#define NO_DERIVATIVE(function, capability)                                    \
    fmi3Status function(fmi3Instance instance,                                 \
                        const fmi3ValueReference unknowns[], size_t nUnknowns, \
                        const fmi3ValueReference knowns[], size_t nKnowns,     \
                        const fmi3Float64 seed[], size_t nSeed,                \
                        fmi3Float64 sensitivity[], size_t nSensitivity)        \
    {                                                                          \
        (void)unknowns;                                                        \
        (void)nUnknowns;                                                       \
        (void)knowns;                                                          \
        (void)nKnowns;                                                         \
        (void)seed;                                                            \
        (void)nSeed;                                                           \
        (void)sensitivity;                                                     \
        (void)nSensitivity;                                                    \
        return NOT_PROVIDED(#function,                                         \
                            "not supported (" capability "=\"false\")");       \
    }

NO_DERIVATIVE(fmi3GetDirectionalDerivative, "providesDirectionalDerivatives")
NO_DERIVATIVE(fmi3GetAdjointDerivative, "providesAdjointDerivatives")

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance,
                                    const fmi3ValueReference vr[], size_t nvr,
                                    const fmi3Int32 orders[],
                                    fmi3Float64 values[], size_t nValues)
{
    (void)vr;
    (void)nvr;
    (void)orders;
    (void)values;
    (void)nValues;
    return NOT_PROVIDED("fmi3GetOutputDerivatives",
                        "not supported (maxOutputDerivativeOrder=\"0\")");
}

/* Clocks: bungee3 has none. NO_CLOCKS_1 (_2): fmi3Error for a clock
   function with one (two) arrays of type A (and B) after the value
   references */
static const char noClocks[] = "bungee3 has no clocks";

#define NO_CLOCKS_2(function, A, B)                                            \
    fmi3Status function(fmi3Instance instance, const fmi3ValueReference vr[],  \
                        size_t nvr, A a[], B b[])                              \
    {                                                                          \
        (void)vr;                                                              \
        (void)nvr;                                                             \
        (void)a;                                                               \
        (void)b;                                                               \
        return NOT_PROVIDED(#function, noClocks);                              \
    }

#define NO_CLOCKS_1(function, A)                                               \
    fmi3Status function(fmi3Instance instance, const fmi3ValueReference vr[],  \
                        size_t nvr, A a[])                                     \
    {                                                                          \
        (void)vr;                                                              \
        (void)nvr;                                                             \
        (void)a;                                                               \
        return NOT_PROVIDED(#function, noClocks);                              \
    }

NO_CLOCKS_2(fmi3GetIntervalDecimal, fmi3Float64, fmi3IntervalQualifier)
NO_CLOCKS_1(fmi3GetShiftDecimal, fmi3Float64)
NO_CLOCKS_2(fmi3GetShiftFraction, fmi3UInt64, fmi3UInt64)
NO_CLOCKS_1(fmi3SetIntervalDecimal, const fmi3Float64)
NO_CLOCKS_2(fmi3SetIntervalFraction, const fmi3UInt64, const fmi3UInt64)
NO_CLOCKS_1(fmi3SetShiftDecimal, const fmi3Float64)
NO_CLOCKS_2(fmi3SetShiftFraction, const fmi3UInt64, const fmi3UInt64)

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance,
                                   const fmi3ValueReference vr[], size_t nvr,
                                   fmi3UInt64 counters[],
                                   fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[])
{
    (void)vr;
    (void)nvr;
    (void)counters;
    (void)resolutions;
    (void)qualifiers;
    return NOT_PROVIDED("fmi3GetIntervalFraction", noClocks);
}

/* --------------- model exchange and scheduled execution: fmi3Error */

/* bungee3 gives no instance for them (fmi3InstantiateModelExchange and
   fmi3InstantiateScheduledExecution return NULL), but importers such as
   the Reference FMUs' fmusim load every function of the standard's headers
   before they instantiate, and refuse a binary that lacks one. */
static fmi3Status coSimulationOnly(fmi3Instance instance, const char* function)
{
    if (!instance)
        return fmi3Error;
    return fail((Instance*)instance, "%s: bungee3 is a co-simulation FMU only",
                function);
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
{
    return coSimulationOnly(instance, "fmi3EnterContinuousTimeMode");
}

fmi3Status fmi3CompletedIntegratorStep(
    fmi3Instance instance, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
    fmi3Boolean* enterEventMode, fmi3Boolean* terminateSimulation)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    (void)enterEventMode;
    (void)terminateSimulation;
    return coSimulationOnly(instance, "fmi3CompletedIntegratorStep");
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time)
{
    (void)time;
    return coSimulationOnly(instance, "fmi3SetTime");
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance,
                                   const fmi3Float64 continuousStates[],
                                   size_t nContinuousStates)
{
    (void)continuousStates;
    (void)nContinuousStates;
    return coSimulationOnly(instance, "fmi3SetContinuousStates");
}

/* fmi3GetContinuousStateDerivatives, fmi3GetEventIndicators,
   fmi3GetContinuousStates and fmi3GetNominalsOfContinuousStates: an
   array and its size */
#define MODEL_EXCHANGE_ARRAY(function)                                         \
    fmi3Status function(fmi3Instance instance, fmi3Float64 values[], size_t n) \
    {                                                                          \
        (void)values;                                                          \
        (void)n;                                                               \
        return coSimulationOnly(instance, #function);                          \
    }

MODEL_EXCHANGE_ARRAY(fmi3GetContinuousStateDerivatives)
MODEL_EXCHANGE_ARRAY(fmi3GetEventIndicators)
MODEL_EXCHANGE_ARRAY(fmi3GetContinuousStates)
MODEL_EXCHANGE_ARRAY(fmi3GetNominalsOfContinuousStates)

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance,
                                          size_t* nEventIndicators)
{
    (void)nEventIndicators;
    return coSimulationOnly(instance, "fmi3GetNumberOfEventIndicators");
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance,
                                           size_t* nContinuousStates)
{
    (void)nContinuousStates;
    return coSimulationOnly(instance, "fmi3GetNumberOfContinuousStates");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance,
                                      fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime)
{
    (void)clockReference;
    (void)activationTime;
    return coSimulationOnly(instance, "fmi3ActivateModelPartition");
}

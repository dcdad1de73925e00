/* eventAsker: an FMI 3.0 co-simulation FMU that does, from t = 0.5 on,
 * what an importer without event mode cannot drive, chosen by its
 * parameter mode: 1 asks for event handling (eventHandlingNeeded), 2
 * returns early (earlyReturn), 3 asks to end the simulation with
 * fmi3Discard; 0 does none of it. Its output y is the time. The functions
 * the importer does not call return fmi3Error. */
#include "fmi3FunctionTypes.h"

#include <stdlib.h>
#include <string.h>

#define EXPORT __attribute__((visibility("default")))

typedef struct {
    double time, mode;
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log;
} Instance;

EXPORT const char* fmi3GetVersion(void)
{
    return "3.0";
}

EXPORT fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String name, fmi3String token, fmi3String resources,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference required[],
    size_t nRequired, fmi3InstanceEnvironment environment,
    fmi3LogMessageCallback log, fmi3IntermediateUpdateCallback update)
{
    (void)name, (void)resources, (void)visible, (void)loggingOn;
    (void)eventModeUsed, (void)earlyReturnAllowed, (void)required;
    (void)nRequired, (void)update;
    if (strcmp(token, "{00000000-0000-0000-0000-0000000e0e17}") != 0)
        return NULL;
    Instance* i = calloc(1, sizeof(Instance));
    i->environment = environment;
    i->log = log;
    return i;
}

EXPORT void fmi3FreeInstance(fmi3Instance instance)
{
    free(instance);
}

EXPORT fmi3Status fmi3EnterInitializationMode(
    fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
    fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime)
{
    (void)toleranceDefined, (void)tolerance, (void)stopTimeDefined;
    (void)stopTime;
    ((Instance*)instance)->time = startTime;
    return fmi3OK;
}

EXPORT fmi3Status fmi3ExitInitializationMode(fmi3Instance instance)
{
    (void)instance;
    return fmi3OK;
}

EXPORT fmi3Status fmi3Terminate(fmi3Instance instance)
{
    (void)instance;
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetFloat64(fmi3Instance instance,
                                 const fmi3ValueReference vrs[], size_t nvr,
                                 fmi3Float64 values[], size_t nValues)
{
    Instance* i = instance;
    if (nvr != nValues)
        return fmi3Error;
    for (size_t k = 0; k < nvr; ++k)
        values[k] = vrs[k] == 1 ? i->time : i->mode;
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetFloat64(fmi3Instance instance,
                                 const fmi3ValueReference vrs[], size_t nvr,
                                 const fmi3Float64 values[], size_t nValues)
{
    Instance* i = instance;
    if (nvr != nValues)
        return fmi3Error;
    for (size_t k = 0; k < nvr; ++k) {
        if (vrs[k] != 2)
            return fmi3Error;
        i->mode = values[k];
    }
    return fmi3OK;
}

EXPORT fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 t,
                             fmi3Float64 h, fmi3Boolean noSetPrior,
                             fmi3Boolean* eventHandlingNeeded,
                             fmi3Boolean* terminateSimulation,
                             fmi3Boolean* earlyReturn,
                             fmi3Float64* lastSuccessfulTime)
{
    Instance* i = instance;
    (void)noSetPrior;
    const int mode = t + h >= 0.5 ? (int)i->mode : 0;
    i->time = mode == 2 || mode == 3 ? t + h / 2 : t + h;
    *eventHandlingNeeded = mode == 1;
    *earlyReturn = mode == 2;
    *terminateSimulation = mode == 3;
    *lastSuccessfulTime = i->time;
    return mode == 3 ? fmi3Discard : fmi3OK;
}

/* The functions the importer resolves but does not call here */
#define NOT_CALLED(name)                                                       \
    EXPORT fmi3Status fmi3##name()                                             \
    {                                                                          \
        return fmi3Error;                                                      \
    }
NOT_CALLED(SetDebugLogging)
NOT_CALLED(Reset)
NOT_CALLED(GetFloat32)
NOT_CALLED(GetInt8)
NOT_CALLED(GetUInt8)
NOT_CALLED(GetInt16)
NOT_CALLED(GetUInt16)
NOT_CALLED(GetInt32)
NOT_CALLED(GetUInt32)
NOT_CALLED(GetInt64)
NOT_CALLED(GetUInt64)
NOT_CALLED(GetBoolean)
NOT_CALLED(GetString)
NOT_CALLED(GetBinary)
NOT_CALLED(SetFloat32)
NOT_CALLED(SetInt8)
NOT_CALLED(SetUInt8)
NOT_CALLED(SetInt16)
NOT_CALLED(SetUInt16)
NOT_CALLED(SetInt32)
NOT_CALLED(SetUInt32)
NOT_CALLED(SetInt64)
NOT_CALLED(SetUInt64)
NOT_CALLED(SetBoolean)
NOT_CALLED(SetString)
NOT_CALLED(SetBinary)
NOT_CALLED(GetFMUState)
NOT_CALLED(SetFMUState)
NOT_CALLED(FreeFMUState)
NOT_CALLED(SerializedFMUStateSize)
NOT_CALLED(SerializeFMUState)
NOT_CALLED(DeserializeFMUState)

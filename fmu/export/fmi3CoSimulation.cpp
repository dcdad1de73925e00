// The fmi3 C entry points of every connector FMU: FMU states (the same
// FmuState code and bytes as FMI 2.0), stepping, and the functions that do
// not apply to this co-simulation FMU (model exchange, scheduled execution,
// event mode, clocks, configuration mode, derivatives), which return
// fmi3Error with the reason logged, as the Reference FMUs do.
#include "EntryPoints3.hpp"
#include "fmi3Functions.h"

namespace {

using fmuExport::anyLiveState;
using fmuExport::Fmi3Instance;
using fmuExport::guarded3;
using fmuExport::modelExchangeOnly;
using fmuExport::requireNonNull;
using fmuExport::savableState;
using fmuExport::unsupported3;
using fmuExport::UsageError;

constexpr const char* noEventMode = "hasEventMode is false: no event mode";
constexpr const char* noClocks = "the FMU declares no clocks";

} // namespace

// A function of a feature the FMU does not have: fmi3Error with the reason
// logged; the parameters after the instance are unnamed
#define FMU_EXPORT_UNSUPPORTED3(Function, reason, ...)                         \
    fmi3Status fmi3##Function(fmi3Instance instance, __VA_ARGS__)              \
    {                                                                          \
        return fmuExport::unsupported3(instance, "fmi3" #Function, reason);    \
    }

extern "C" {

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState)
{
    return guarded3(instance, "fmi3GetFMUState", savableState,
                    [&](Fmi3Instance& i) {
                        requireNonNull(FMUState, "FMUState");
                        *FMUState = i.core().getState(*FMUState);
                    });
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState)
{
    return guarded3(instance, "fmi3SetFMUState", anyLiveState,
                    [&](Fmi3Instance& i) { i.core().setState(FMUState); });
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState)
{
    return guarded3(instance, "fmi3FreeFMUState", anyLiveState,
                    [&](Fmi3Instance& i) {
                        requireNonNull(FMUState, "FMUState");
                        i.core().freeState(*FMUState);
                        *FMUState = nullptr;
                    });
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance,
                                      fmi3FMUState FMUState, size_t* size)
{
    return guarded3(instance, "fmi3SerializedFMUStateSize", anyLiveState,
                    [&](Fmi3Instance& i) {
                        requireNonNull(size, "size");
                        *size = i.core().serializedStateSize(FMUState);
                    });
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                 fmi3Byte serializedState[], size_t size)
{
    return guarded3(
        instance, "fmi3SerializeFMUState", anyLiveState, [&](Fmi3Instance& i) {
            i.core().serializeState(
                FMUState, reinterpret_cast<fmi2Byte*>(serializedState), size);
        });
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance,
                                   const fmi3Byte serializedState[],
                                   size_t size, fmi3FMUState* FMUState)
{
    return guarded3(instance, "fmi3DeserializeFMUState", anyLiveState,
                    [&](Fmi3Instance& i) {
                        requireNonNull(FMUState, "FMUState");
                        *FMUState = i.core().deserializeState(
                            reinterpret_cast<const fmi2Byte*>(serializedState),
                            size, *FMUState);
                    });
}

fmi3Status fmi3DoStep(fmi3Instance instance,
                      fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean* eventHandlingNeeded,
                      fmi3Boolean* terminateSimulation,
                      fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    return guarded3(
        instance, "fmi3DoStep", fmuExport::stepComplete, [&](Fmi3Instance& i) {
            requireNonNull(eventHandlingNeeded, "eventHandlingNeeded");
            requireNonNull(terminateSimulation, "terminateSimulation");
            requireNonNull(earlyReturn, "earlyReturn");
            requireNonNull(lastSuccessfulTime, "lastSuccessfulTime");
            *eventHandlingNeeded = false;
            *terminateSimulation = false;
            *earlyReturn = false;
            *lastSuccessfulTime = i.core().time();
            i.core().doStep(currentCommunicationPoint, communicationStepSize);
            *lastSuccessfulTime = i.core().time();
        });
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance)
{
    return unsupported3(instance, "fmi3EnterEventMode", noEventMode);
}

fmi3Status fmi3EnterStepMode(fmi3Instance instance)
{
    return unsupported3(instance, "fmi3EnterStepMode",
                        "hasEventMode is false: the FMU enters step mode "
                        "from fmi3ExitInitializationMode");
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
{
    return unsupported3(instance, "fmi3EvaluateDiscreteStates", noEventMode);
}

FMU_EXPORT_UNSUPPORTED3(UpdateDiscreteStates, noEventMode, fmi3Boolean*,
                        fmi3Boolean*, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                        fmi3Float64*)

FMU_EXPORT_UNSUPPORTED3(GetNumberOfVariableDependencies,
                        "the dependencies are those of modelDescription.xml's "
                        "ModelStructure",
                        fmi3ValueReference, size_t*)

FMU_EXPORT_UNSUPPORTED3(GetVariableDependencies,
                        "the dependencies are those of modelDescription.xml's "
                        "ModelStructure",
                        fmi3ValueReference, size_t[], fmi3ValueReference[],
                        size_t[], fmi3DependencyKind[], size_t)

FMU_EXPORT_UNSUPPORTED3(GetDirectionalDerivative,
                        "providesDirectionalDerivative is false",
                        const fmi3ValueReference[], size_t,
                        const fmi3ValueReference[], size_t, const fmi3Float64[],
                        size_t, fmi3Float64[], size_t)

FMU_EXPORT_UNSUPPORTED3(GetAdjointDerivative,
                        "providesAdjointDerivatives is false",
                        const fmi3ValueReference[], size_t,
                        const fmi3ValueReference[], size_t, const fmi3Float64[],
                        size_t, fmi3Float64[], size_t)

FMU_EXPORT_UNSUPPORTED3(GetOutputDerivatives, "maxOutputDerivativeOrder is 0",
                        const fmi3ValueReference[], size_t, const fmi3Int32[],
                        fmi3Float64[], size_t)

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance)
{
    return unsupported3(instance, "fmi3EnterConfigurationMode",
                        "the FMU has no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance)
{
    return unsupported3(instance, "fmi3ExitConfigurationMode",
                        "the FMU has no structural parameters");
}

FMU_EXPORT_UNSUPPORTED3(GetIntervalDecimal, noClocks,
                        const fmi3ValueReference[], size_t, fmi3Float64[],
                        fmi3IntervalQualifier[])

FMU_EXPORT_UNSUPPORTED3(GetIntervalFraction, noClocks,
                        const fmi3ValueReference[], size_t, fmi3UInt64[],
                        fmi3UInt64[], fmi3IntervalQualifier[])

FMU_EXPORT_UNSUPPORTED3(GetShiftDecimal, noClocks, const fmi3ValueReference[],
                        size_t, fmi3Float64[])

FMU_EXPORT_UNSUPPORTED3(GetShiftFraction, noClocks, const fmi3ValueReference[],
                        size_t, fmi3UInt64[], fmi3UInt64[])

FMU_EXPORT_UNSUPPORTED3(SetIntervalDecimal, noClocks,
                        const fmi3ValueReference[], size_t, const fmi3Float64[])

FMU_EXPORT_UNSUPPORTED3(SetIntervalFraction, noClocks,
                        const fmi3ValueReference[], size_t, const fmi3UInt64[],
                        const fmi3UInt64[])

FMU_EXPORT_UNSUPPORTED3(SetShiftDecimal, noClocks, const fmi3ValueReference[],
                        size_t, const fmi3Float64[])

FMU_EXPORT_UNSUPPORTED3(SetShiftFraction, noClocks, const fmi3ValueReference[],
                        size_t, const fmi3UInt64[], const fmi3UInt64[])

FMU_EXPORT_UNSUPPORTED3(ActivateModelPartition,
                        "scheduled execution is not supported",
                        fmi3ValueReference, fmi3Float64)

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
{
    return unsupported3(instance, "fmi3EnterContinuousTimeMode",
                        modelExchangeOnly);
}

FMU_EXPORT_UNSUPPORTED3(CompletedIntegratorStep, modelExchangeOnly, fmi3Boolean,
                        fmi3Boolean*, fmi3Boolean*)

FMU_EXPORT_MODEL_EXCHANGE(FMU_EXPORT_UNSUPPORTED3, fmi3Float64)

FMU_EXPORT_UNSUPPORTED3(GetContinuousStateDerivatives, modelExchangeOnly,
                        fmi3Float64[], size_t)

FMU_EXPORT_UNSUPPORTED3(GetNumberOfEventIndicators, modelExchangeOnly, size_t*)

FMU_EXPORT_UNSUPPORTED3(GetNumberOfContinuousStates, modelExchangeOnly, size_t*)

} // extern "C"

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
using fmuExport::requireNonNull;
using fmuExport::savableState;
using fmuExport::unsupported3;
using fmuExport::UsageError;

constexpr const char* modelExchangeOnly
    = "model exchange is not supported: this is a co-simulation FMU";
constexpr const char* noEventMode = "hasEventMode is false: no event mode";
constexpr const char* noClocks = "the FMU declares no clocks";

} // namespace

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

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean*,
                                    fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                                    fmi3Boolean*, fmi3Float64*)
{
    return unsupported3(instance, "fmi3UpdateDiscreteStates", noEventMode);
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                               fmi3ValueReference, size_t*)
{
    return unsupported3(instance, "fmi3GetNumberOfVariableDependencies",
                        "the dependencies are those of modelDescription.xml's "
                        "ModelStructure");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance,
                                       fmi3ValueReference, size_t[],
                                       fmi3ValueReference[], size_t[],
                                       fmi3DependencyKind[], size_t)
{
    return unsupported3(instance, "fmi3GetVariableDependencies",
                        "the dependencies are those of modelDescription.xml's "
                        "ModelStructure");
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance,
                                        const fmi3ValueReference[], size_t,
                                        const fmi3ValueReference[], size_t,
                                        const fmi3Float64[], size_t,
                                        fmi3Float64[], size_t)
{
    return unsupported3(instance, "fmi3GetDirectionalDerivative",
                        "providesDirectionalDerivative is false");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance,
                                    const fmi3ValueReference[], size_t,
                                    const fmi3ValueReference[], size_t,
                                    const fmi3Float64[], size_t, fmi3Float64[],
                                    size_t)
{
    return unsupported3(instance, "fmi3GetAdjointDerivative",
                        "providesAdjointDerivatives is false");
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance,
                                    const fmi3ValueReference[], size_t,
                                    const fmi3Int32[], fmi3Float64[], size_t)
{
    return unsupported3(instance, "fmi3GetOutputDerivatives",
                        "maxOutputDerivativeOrder is 0");
}

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

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance,
                                  const fmi3ValueReference[], size_t,
                                  fmi3Float64[], fmi3IntervalQualifier[])
{
    return unsupported3(instance, "fmi3GetIntervalDecimal", noClocks);
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance,
                                   const fmi3ValueReference[], size_t,
                                   fmi3UInt64[], fmi3UInt64[],
                                   fmi3IntervalQualifier[])
{
    return unsupported3(instance, "fmi3GetIntervalFraction", noClocks);
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance,
                               const fmi3ValueReference[], size_t,
                               fmi3Float64[])
{
    return unsupported3(instance, "fmi3GetShiftDecimal", noClocks);
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance,
                                const fmi3ValueReference[], size_t,
                                fmi3UInt64[], fmi3UInt64[])
{
    return unsupported3(instance, "fmi3GetShiftFraction", noClocks);
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance,
                                  const fmi3ValueReference[], size_t,
                                  const fmi3Float64[])
{
    return unsupported3(instance, "fmi3SetIntervalDecimal", noClocks);
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance,
                                   const fmi3ValueReference[], size_t,
                                   const fmi3UInt64[], const fmi3UInt64[])
{
    return unsupported3(instance, "fmi3SetIntervalFraction", noClocks);
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance,
                               const fmi3ValueReference[], size_t,
                               const fmi3Float64[])
{
    return unsupported3(instance, "fmi3SetShiftDecimal", noClocks);
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance,
                                const fmi3ValueReference[], size_t,
                                const fmi3UInt64[], const fmi3UInt64[])
{
    return unsupported3(instance, "fmi3SetShiftFraction", noClocks);
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference,
                                      fmi3Float64)
{
    return unsupported3(instance, "fmi3ActivateModelPartition",
                        "scheduled execution is not supported");
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
{
    return unsupported3(instance, "fmi3EnterContinuousTimeMode",
                        modelExchangeOnly);
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean,
                                       fmi3Boolean*, fmi3Boolean*)
{
    return unsupported3(instance, "fmi3CompletedIntegratorStep",
                        modelExchangeOnly);
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64)
{
    return unsupported3(instance, "fmi3SetTime", modelExchangeOnly);
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64[],
                                   size_t)
{
    return unsupported3(instance, "fmi3SetContinuousStates", modelExchangeOnly);
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance,
                                             fmi3Float64[], size_t)
{
    return unsupported3(instance, "fmi3GetContinuousStateDerivatives",
                        modelExchangeOnly);
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64[], size_t)
{
    return unsupported3(instance, "fmi3GetEventIndicators", modelExchangeOnly);
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64[], size_t)
{
    return unsupported3(instance, "fmi3GetContinuousStates", modelExchangeOnly);
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance,
                                             fmi3Float64[], size_t)
{
    return unsupported3(instance, "fmi3GetNominalsOfContinuousStates",
                        modelExchangeOnly);
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t*)
{
    return unsupported3(instance, "fmi3GetNumberOfEventIndicators",
                        modelExchangeOnly);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t*)
{
    return unsupported3(instance, "fmi3GetNumberOfContinuousStates",
                        modelExchangeOnly);
}

} // extern "C"

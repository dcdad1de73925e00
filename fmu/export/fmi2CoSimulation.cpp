// The fmi2 C entry points of every connector FMU: FMU states, stepping,
// status queries, and the functions a co-simulation FMU does not provide
// (model exchange, directional derivatives, input interpolation), which
// return fmi2Error with a logged reason.
#include "EntryPoints.hpp"
#include "fmi2Functions.h"

namespace {

using fmuExport::anyLiveState;
using fmuExport::FmuInstance;
using fmuExport::guarded;
using fmuExport::modelExchangeOnly;
using fmuExport::requireNonNull;
using fmuExport::savableState;
using fmuExport::unsupported;
using fmuExport::UsageError;

constexpr const char* noPending
    = "fmi2DoStep runs synchronously and never returns fmi2Pending";

FmuInstance& instance(fmi2Component c)
{
    return *static_cast<FmuInstance*>(c);
}

//- An fmi2Get<Type>Status that knows one status kind: *value = answer()
//  for `kind`, UsageError(`only`) for any other
template <class Value, class Answer>
fmi2Status status(fmi2Component c, const char* function, fmi2StatusKind s,
                  fmi2StatusKind kind, const char* only, Value* value,
                  Answer answer)
{
    return guarded(c, function, anyLiveState, [&] {
        requireNonNull(value, "value");
        if (s != kind) {
            throw UsageError(only);
        }
        *value = answer();
    });
}

} // namespace

extern "C" {

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate)
{
    return guarded(c, "fmi2GetFMUstate", savableState, [&] {
        requireNonNull(FMUstate, "FMUstate");
        *FMUstate = instance(c).getState(*FMUstate);
    });
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    return guarded(c, "fmi2SetFMUstate", anyLiveState,
                   [&] { instance(c).setState(FMUstate); });
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate)
{
    return guarded(c, "fmi2FreeFMUstate", anyLiveState, [&] {
        requireNonNull(FMUstate, "FMUstate");
        instance(c).freeState(*FMUstate);
        *FMUstate = nullptr;
    });
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate,
                                      size_t* size)
{
    return guarded(c, "fmi2SerializedFMUstateSize", anyLiveState, [&] {
        requireNonNull(size, "size");
        *size = instance(c).serializedStateSize(FMUstate);
    });
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                 fmi2Byte serializedState[], size_t size)
{
    return guarded(c, "fmi2SerializeFMUstate", anyLiveState, [&] {
        instance(c).serializeState(FMUstate, serializedState, size);
    });
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c,
                                   const fmi2Byte serializedState[],
                                   size_t size, fmi2FMUstate* FMUstate)
{
    return guarded(c, "fmi2DeSerializeFMUstate", anyLiveState, [&] {
        requireNonNull(FMUstate, "FMUstate");
        *FMUstate
            = instance(c).deserializeState(serializedState, size, *FMUstate);
    });
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    return guarded(c, "fmi2DoStep", fmuExport::stepComplete, [&] {
        instance(c).doStep(currentCommunicationPoint, communicationStepSize);
    });
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    return unsupported(c, "fmi2CancelStep", noPending);
}

FMU_EXPORT_UNSUPPORTED2(GetStatus, noPending, const fmi2StatusKind, fmi2Status*)

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s,
                             fmi2Real* value)
{
    return status(c, "fmi2GetRealStatus", s, fmi2LastSuccessfulTime,
                  "only fmi2LastSuccessfulTime is available", value,
                  [&] { return instance(c).time(); });
}

FMU_EXPORT_UNSUPPORTED2(GetIntegerStatus,
                        "no Integer status is defined in FMI 2.0",
                        const fmi2StatusKind, fmi2Integer*)

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s,
                                fmi2Boolean* value)
{
    return status(c, "fmi2GetBooleanStatus", s, fmi2Terminated,
                  "only fmi2Terminated is available", value,
                  [] { return fmi2False; });
}

FMU_EXPORT_UNSUPPORTED2(GetStringStatus, noPending, const fmi2StatusKind,
                        fmi2String*)

FMU_EXPORT_UNSUPPORTED2(SetRealInputDerivatives,
                        "canInterpolateInputs is false",
                        const fmi2ValueReference[], size_t, const fmi2Integer[],
                        const fmi2Real[])

FMU_EXPORT_UNSUPPORTED2(GetRealOutputDerivatives,
                        "maxOutputDerivativeOrder is 0",
                        const fmi2ValueReference[], size_t, const fmi2Integer[],
                        fmi2Real[])

FMU_EXPORT_UNSUPPORTED2(GetDirectionalDerivative,
                        "providesDirectionalDerivative is false",
                        const fmi2ValueReference[], size_t,
                        const fmi2ValueReference[], size_t, const fmi2Real[],
                        fmi2Real[])

fmi2Status fmi2EnterEventMode(fmi2Component c)
{
    return unsupported(c, "fmi2EnterEventMode", modelExchangeOnly);
}

FMU_EXPORT_UNSUPPORTED2(NewDiscreteStates, modelExchangeOnly, fmi2EventInfo*)

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c)
{
    return unsupported(c, "fmi2EnterContinuousTimeMode", modelExchangeOnly);
}

FMU_EXPORT_UNSUPPORTED2(CompletedIntegratorStep, modelExchangeOnly, fmi2Boolean,
                        fmi2Boolean*, fmi2Boolean*)

FMU_EXPORT_MODEL_EXCHANGE(FMU_EXPORT_UNSUPPORTED2, fmi2Real)

FMU_EXPORT_UNSUPPORTED2(GetDerivatives, modelExchangeOnly, fmi2Real[], size_t)

} // extern "C"

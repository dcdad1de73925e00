// Helpers shared by the fmi2 entry points (fmi2Functions.cpp,
// fmi2CoSimulation.cpp) and, through EntryPoints3.hpp, the fmi3 ones: the
// state masks of FMI 2.0 co-simulation and the guard that every call goes
// through.
#ifndef FMU_EXPORT_ENTRYPOINTS_HPP
#define FMU_EXPORT_ENTRYPOINTS_HPP

#include <string>

#include "FmuInstance.hpp"

namespace fmuExport {

constexpr unsigned anyLiveState
    = instantiated | initializationMode | stepComplete | terminated | error;
constexpr unsigned savableState
    = instantiated | initializationMode | stepComplete | terminated;
constexpr unsigned readableState
    = initializationMode | stepComplete | terminated | error;
constexpr unsigned writableState
    = instantiated | initializationMode | stepComplete;

template <class Body>
inline fmi2Status guarded(fmi2Component c, const char* function,
                          unsigned allowed, Body&& body)
{
    if (c == nullptr) {
        return fmi2Error;
    }
    return static_cast<FmuInstance*>(c)->call(function, allowed, body);
}

//- UsageError "<argument> is NULL" for a NULL pointer argument
inline void requireNonNull(const void* pointer, const char* argument)
{
    if (pointer == nullptr) {
        throw UsageError(std::string(argument) + " is NULL");
    }
}

//- Why a co-simulation FMU refuses the model-exchange functions
constexpr const char* modelExchangeOnly
    = "model exchange is not supported: this is a co-simulation FMU";

//- Every function of the standard that a co-simulation FMU does not provide
inline fmi2Status unsupported(fmi2Component c, const char* function,
                              const char* reason)
{
    return guarded(c, function, anyLiveState | fatal,
                   [&] { throw UsageError(reason); });
}

} // namespace fmuExport

// A function of a feature the FMU does not have: fmi2Error with the reason
// logged; the parameters after the instance are unnamed
#define FMU_EXPORT_UNSUPPORTED2(Function, reason, ...)                         \
    fmi2Status fmi2##Function(fmi2Component c, __VA_ARGS__)                    \
    {                                                                          \
        return fmuExport::unsupported(c, "fmi2" #Function, reason);            \
    }

// The model-exchange functions that FMI 2.0 and FMI 3.0 declare alike, as
// Unsupported(Function, reason, the parameters after the instance), Real the
// version's floating-point type
// clang-format off
#define FMU_EXPORT_MODEL_EXCHANGE(Unsupported, Real)                           \
    Unsupported(SetTime, fmuExport::modelExchangeOnly, Real)                   \
    Unsupported(SetContinuousStates, fmuExport::modelExchangeOnly,             \
                const Real[], size_t)                                          \
    Unsupported(GetEventIndicators, fmuExport::modelExchangeOnly, Real[],      \
                size_t)                                                        \
    Unsupported(GetContinuousStates, fmuExport::modelExchangeOnly, Real[],     \
                size_t)                                                        \
    Unsupported(GetNominalsOfContinuousStates, fmuExport::modelExchangeOnly,   \
                Real[], size_t)
// clang-format on

#endif

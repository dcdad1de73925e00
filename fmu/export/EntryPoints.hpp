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

//- Every function of the standard that a co-simulation FMU does not provide
inline fmi2Status unsupported(fmi2Component c, const char* function,
                              const char* reason)
{
    return guarded(c, function, anyLiveState | fatal,
                   [&] { throw UsageError(reason); });
}

} // namespace fmuExport

#endif

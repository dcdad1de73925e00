// Floating-point traps masked around every call into an FMU (fmi2
// functions, and dlopen and dlclose, which run its static constructors and
// destructors): MaskFpTraps, fmuImport.hpp.
#ifndef FMUIMPORT_FPTRAPS_HPP
#define FMUIMPORT_FPTRAPS_HPP

#include "fmuImport/fmuImport.hpp"

namespace fmuImport {

// Calls the FMU function f with args, traps masked.
template <class F, class... Args> auto callFmu(F* f, Args&&... args)
{
    const MaskFpTraps masked;
    return f(static_cast<Args&&>(args)...);
}

} // namespace fmuImport

#endif

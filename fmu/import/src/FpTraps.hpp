// Floating-point traps masked around calls into an FMU.
//
// OpenFOAM (FOAM_SIGFPE) enables the FE_DIVBYZERO, FE_INVALID and
// FE_OVERFLOW traps with feenableexcept. An FMU is written for the default
// IEEE environment: an overflow in its own arithmetic would then kill the
// host with SIGFPE instead of giving an infinity the FMU checks and reports
// as fmi2Error. So every call into FMU code (fmi2 functions, and dlopen and
// dlclose, which run its static constructors and destructors) runs with the
// traps masked, and the caller's environment is restored afterwards.
#ifndef FMUIMPORT_FPTRAPS_HPP
#define FMUIMPORT_FPTRAPS_HPP

#include <cfenv>

namespace fmuImport {

class MaskFpTraps
{
public:
    // fegetexcept (glibc) only reads the control word, so a caller without
    // traps, the usual case, pays almost nothing on this hot path.
    MaskFpTraps() : traps_(fegetexcept())
    {
        if (traps_ == 0) return;
        fegetexceptflag(&flags_, FE_ALL_EXCEPT);
        fedisableexcept(traps_);
    }

    // Restores the caller's status flags before its traps: the flags the
    // FMU raised are the FMU's business (it reports non-finite results
    // itself), and a flag left set under an enabled trap would fire at the
    // caller's next x87 instruction.
    ~MaskFpTraps()
    {
        if (traps_ == 0) return;
        fesetexceptflag(&flags_, FE_ALL_EXCEPT);
        feenableexcept(traps_);
    }

    MaskFpTraps(const MaskFpTraps&) = delete;
    MaskFpTraps& operator=(const MaskFpTraps&) = delete;

private:
    int traps_;
    fexcept_t flags_{};
};

// Calls the FMU function f with args, traps masked.
template <class F, class... Args>
auto callFmu(F* f, Args&&... args)
{
    const MaskFpTraps masked;
    return f(static_cast<Args&&>(args)...);
}

}  // namespace fmuImport

#endif

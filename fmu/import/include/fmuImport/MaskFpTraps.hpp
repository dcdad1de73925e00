// fmuImport: the host's floating-point traps masked around calls into an FMU.
// Part of the importer's public interface (fmuImport.hpp includes every
// part), C++11 like the rest of it.
#ifndef FMUIMPORT_MASK_FP_TRAPS_HPP
#define FMUIMPORT_MASK_FP_TRAPS_HPP

#include <cfenv>

namespace fmuImport {

// Masks the caller's floating-point traps for its lifetime. OpenFOAM
// (FOAM_SIGFPE) enables the FE_DIVBYZERO, FE_INVALID and FE_OVERFLOW traps
// with feenableexcept. An FMU is written for the default IEEE environment:
// an overflow in its own arithmetic would then kill the host with SIGFPE
// instead of giving an infinity the FMU checks and reports as fmi2Error. So
// every call into FMU code runs inside one of these, and the caller's
// environment is restored afterwards. Switching traps costs a few hundred
// nanoseconds; a caller that makes several calls in a row (a connector's
// evaluation) masks once around them all, and the calls inside then find no
// trap to switch.
class MaskFpTraps {
public:
    // fegetexcept (glibc) only reads the control word, so a caller without
    // traps, the usual case, pays almost nothing.
    MaskFpTraps() : traps_(fegetexcept())
    {
        if (traps_ == 0)
            return;
        fegetexceptflag(&flags_, FE_ALL_EXCEPT);
        fedisableexcept(traps_);
    }

    // Restores the caller's status flags before its traps: the flags the
    // FMU raised are the FMU's business (it reports non-finite results
    // itself), and a flag left set under an enabled trap would fire at the
    // caller's next x87 instruction.
    ~MaskFpTraps()
    {
        if (traps_ == 0)
            return;
        fesetexceptflag(&flags_, FE_ALL_EXCEPT);
        feenableexcept(traps_);
    }

    MaskFpTraps(const MaskFpTraps&) = delete;
    MaskFpTraps& operator=(const MaskFpTraps&) = delete;

private:
    int traps_;
    fexcept_t flags_ {};
};

} // namespace fmuImport

#endif

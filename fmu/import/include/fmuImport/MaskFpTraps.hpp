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
// environment is restored afterwards: its status flags (the flags the FMU
// raised are the FMU's business: it reports non-finite results itself),
// then its traps (a flag left set under an enabled trap would fire at the
// caller's next x87 instruction). A caller that makes several calls in a
// row (a connector's evaluation) masks once around them all, and the calls
// inside then find no trap to switch.
//
// On x86-64 the x87 control and status words and the SSE MXCSR are read
// and written directly (fnstcw, fnstsw, stmxcsr; fldcw, ldmxcsr), and the
// x87 flags are restored only when the FMU changed them: glibc's
// fedisableexcept, feenableexcept and fesetexceptflag save and load the
// whole x87 environment every time (a switch and back: 300 ns against
// 210 ns on the project's test machine, of which fldcw, changing the x87
// masks, takes 150). Elsewhere glibc's.
class MaskFpTraps {
public:
#if defined(__x86_64__) && defined(__GNUC__)
    MaskFpTraps()
    {
        __asm__ __volatile__("fnstcw %0" : "=m"(x87Control_));
        __asm__ __volatile__("stmxcsr %0" : "=m"(sse_));
        // A trap is enabled where its mask bit is clear: bits 0-5 of the
        // control word, 7-12 of MXCSR, in the order of the FE_ flags
        traps_ = (~x87Control_ | ~(sse_ >> 7)) & FE_ALL_EXCEPT;
        if (traps_ == 0)
            return;
        unsigned short status;
        __asm__ __volatile__("fnstsw %0" : "=m"(status));
        x87Flags_ = status & FE_ALL_EXCEPT;
        const unsigned short x87Masked = x87Control_ | FE_ALL_EXCEPT;
        const unsigned int sseMasked = sse_ | (FE_ALL_EXCEPT << 7);
        __asm__ __volatile__("fldcw %0" : : "m"(x87Masked));
        __asm__ __volatile__("ldmxcsr %0" : : "m"(sseMasked));
    }

    ~MaskFpTraps()
    {
        if (traps_ == 0)
            return;
        // The caller's x87 flags back while still masked, when the FMU
        // changed them (seldom: x86-64 code computes doubles with SSE);
        // MXCSR holds the SSE flags and traps
        unsigned short status;
        __asm__ __volatile__("fnstsw %0" : "=m"(status));
        if ((status & FE_ALL_EXCEPT) != x87Flags_) {
            const fexcept_t flags = static_cast<fexcept_t>(x87Flags_);
            fesetexceptflag(&flags, FE_ALL_EXCEPT);
        }
        __asm__ __volatile__("fldcw %0" : : "m"(x87Control_));
        __asm__ __volatile__("ldmxcsr %0" : : "m"(sse_));
    }
#else
    // fegetexcept (glibc) only reads the control word, so a caller without
    // traps, the usual case, pays almost nothing.
    MaskFpTraps() : traps_(fegetexcept())
    {
        if (traps_ == 0)
            return;
        fegetexceptflag(&flags_, FE_ALL_EXCEPT);
        fedisableexcept(traps_);
    }

    ~MaskFpTraps()
    {
        if (traps_ == 0)
            return;
        fesetexceptflag(&flags_, FE_ALL_EXCEPT);
        feenableexcept(traps_);
    }
#endif

    MaskFpTraps(const MaskFpTraps&) = delete;
    MaskFpTraps& operator=(const MaskFpTraps&) = delete;

private:
    int traps_;
#if defined(__x86_64__) && defined(__GNUC__)
    unsigned short x87Control_;
    unsigned int sse_;
    int x87Flags_ = 0;
#else
    fexcept_t flags_ {};
#endif
};

} // namespace fmuImport

#endif

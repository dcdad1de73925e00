// fmuImport: the host's floating-point traps masked around calls into an FMU.
// Part of the importer's public interface (fmuImport.hpp includes every
// part), C++11 like the rest of it.
#ifndef FMUIMPORT_MASK_FP_TRAPS_HPP
#define FMUIMPORT_MASK_FP_TRAPS_HPP

#include <cfenv>

namespace fmuImport {

// Masks the caller's floating-point traps for its lifetime. OpenFOAM
// (FOAM_SIGFPE) enables the FE_DIVBYZERO, FE_INVALID and FE_OVERFLOW traps
// with feenableexcept, which unmasks them in both the SSE MXCSR (double
// maths) and the x87 control word (long double maths): control word 0x372,
// MXCSR 0x1900. An FMU is written for the default IEEE environment: an
// overflow in its own arithmetic would then kill the host with SIGFPE
// instead of giving an infinity the FMU checks and reports as fmi2Error. So
// every call into FMU code runs inside one of these, and the caller's
// environment is restored afterwards: its status flags (the flags the FMU
// raised are the FMU's business: it reports non-finite results itself),
// then its traps. A caller that makes several calls in a row (a connector's
// evaluation) masks once around them all, and the calls inside then find no
// trap to switch.
//
// On x86-64 the registers are read and written directly. MXCSR: stmxcsr,
// ldmxcsr. The x87 unit, when its control word unmasks a trap: fnstenv
// saves its environment (control and status words) and masks every x87
// exception, fldenv restores it, traps and flags together. The x87 stack
// is empty at both ends (calls lie between them: the x86-64 ABI). That
// pair costs less than switching the control word with fldcw and back:
// fldcw is slow whenever it changes an exception mask (Intel's optimization
// manual; on the project's test machine, an AMD EPYC, 2 x 100 ns against
// 2 x 20 ns for ldmxcsr). With the x87 traps masked already (a host that
// enables SSE traps only) the control word is left alone and only the x87
// flags the FMU changed are set back. Elsewhere glibc's functions.
class MaskFpTraps {
public:
#if defined(__x86_64__) && defined(__GNUC__)
    MaskFpTraps()
    {
        unsigned short x87Control;
        __asm__ __volatile__("fnstcw %0" : "=m"(x87Control));
        __asm__ __volatile__("stmxcsr %0" : "=m"(sse_));
        // A trap is enabled where its mask bit is clear: bits 0-5 of the
        // control word, 7-12 of MXCSR, in the order of the FE_ flags
        x87Traps_ = ~x87Control & FE_ALL_EXCEPT;
        traps_ = x87Traps_ | (~(sse_ >> 7) & FE_ALL_EXCEPT);
        if (traps_ == 0)
            return;
        if (x87Traps_ != 0) {
            __asm__ __volatile__("fnstenv %0" : "=m"(x87Environment_));
        } else {
            unsigned short status;
            __asm__ __volatile__("fnstsw %0" : "=m"(status));
            x87Flags_ = status & FE_ALL_EXCEPT;
        }
        const unsigned int sseMasked = sse_ | (FE_ALL_EXCEPT << 7);
        __asm__ __volatile__("ldmxcsr %0" : : "m"(sseMasked));
    }

    ~MaskFpTraps()
    {
        if (traps_ == 0)
            return;
        if (x87Traps_ != 0) {
            __asm__ __volatile__("fldenv %0" : : "m"(x87Environment_));
        } else {
            // The caller's x87 flags back when the FMU changed them
            // (seldom: x86-64 code computes doubles with SSE)
            unsigned short status;
            __asm__ __volatile__("fnstsw %0" : "=m"(status));
            if ((status & FE_ALL_EXCEPT) != x87Flags_) {
                const fexcept_t flags = static_cast<fexcept_t>(x87Flags_);
                fesetexceptflag(&flags, FE_ALL_EXCEPT);
            }
        }
        // MXCSR holds the SSE flags and traps
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
    int x87Traps_;
    unsigned int sse_;
    int x87Flags_ = 0;
    // The x87 environment in fnstenv's 28-byte form
    unsigned char x87Environment_[28];
#else
    fexcept_t flags_ {};
#endif
};

} // namespace fmuImport

#endif

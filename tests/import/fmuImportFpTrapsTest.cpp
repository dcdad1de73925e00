// Floating-point traps of the host (OpenFOAM's FOAM_SIGFPE) must not reach
// into the FMU: an overflow the FMU reports as fmi2Error stays an Error, and
// the caller's traps are as they were after the call.
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

#include <cfenv>

namespace {

using fixtures::fmuPath;

const int foamTraps
    = FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW; // what FOAM_SIGFPE enables

// Enables the traps for the lifetime of the object, as OpenFOAM does.
class TrapsEnabled {
public:
    TrapsEnabled()
    {
        std::feclearexcept(FE_ALL_EXCEPT);
        feenableexcept(foamTraps);
    }
    ~TrapsEnabled()
    {
        fedisableexcept(FE_ALL_EXCEPT);
        std::feclearexcept(FE_ALL_EXCEPT);
    }
    TrapsEnabled(const TrapsEnabled&) = delete;
    TrapsEnabled& operator=(const TrapsEnabled&) = delete;
};

// overflowStep stepped: its overflow (in long double first, then in
// double) is its fmi2Error, not the caller's SIGFPE
void expectOverflowIsAnError()
{
    const fmuImport::Fmu fmu(fmuPath("overflowStep"));
    fmuImport::Instance instance(
        fmu, "overflow",
        [](const std::string&, int, const std::string&, const std::string&) {});
    instance.setupExperiment(0.0);
    instance.enterInitializationMode();
    instance.exitInitializationMode();
    fixtures::expectErrorSaying([&] { instance.doStep(0.0, 0.1); },
                                "y = gain * DBL_MAX overflowed (gain = 10)",
                                "the overflowing step did not throw");
}

TEST(FpTraps, OverflowInTheFmuIsItsErrorNotSigfpe)
{
    const TrapsEnabled traps;
    expectOverflowIsAnError();
    EXPECT_EQ(fegetexcept(), foamTraps) << "the caller's trap mask changed";
    EXPECT_EQ(std::fetestexcept(FE_OVERFLOW), 0)
        << "the FMU's overflow flag leaked to the caller";
}

#if defined(__x86_64__) && defined(__GNUC__)
// foam-fmi-bridge masks the x87 traps of OpenFOAM's solver thread for good
// (OpenFOAM has no long double arithmetic) and leaves its SSE traps: the
// FMU's long double overflow (overflowStep overflows in long double first)
// still must not trap, and the caller's x87 mask and SSE traps survive
TEST(FpTraps, HostWithSseTrapsOnlyStillProtectsTheFmu)
{
    const TrapsEnabled traps;
    unsigned short control;
    __asm__ __volatile__("fnstcw %0" : "=m"(control));
    control |= FE_ALL_EXCEPT;
    __asm__ __volatile__("fldcw %0" : : "m"(control));
    unsigned int sse;
    __asm__ __volatile__("stmxcsr %0" : "=m"(sse));
    expectOverflowIsAnError();
    unsigned short controlAfter;
    __asm__ __volatile__("fnstcw %0" : "=m"(controlAfter));
    unsigned int sseAfter;
    __asm__ __volatile__("stmxcsr %0" : "=m"(sseAfter));
    EXPECT_EQ(controlAfter, control) << "the caller's x87 control word changed";
    // (MXCSR's exception masks, bits 7-12; its flags may be the caller's
    // own, such as inexact from formatting the error's message)
    EXPECT_EQ((sseAfter >> 7) & FE_ALL_EXCEPT, (sse >> 7) & FE_ALL_EXCEPT)
        << "the caller's SSE traps changed";
    EXPECT_EQ(std::fetestexcept(FE_OVERFLOW), 0)
        << "the FMU's overflow flag leaked to the caller";
}
#endif

TEST(FpTraps, CallersTrapsAndFlagsSurviveEveryCall)
{
    const TrapsEnabled traps;
    {
        const fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
        fmuImport::Instance lag(fmu, "lag1");
        lag.setupExperiment(0.0);
        lag.enterInitializationMode();
        lag.exitInitializationMode();
        lag.doStep(0.0, 0.1);
        EXPECT_EQ(fegetexcept(), foamTraps);
    }
    EXPECT_EQ(fegetexcept(), foamTraps)
        << "freeing the instance or closing the FMU changed the trap mask";
}

} // namespace

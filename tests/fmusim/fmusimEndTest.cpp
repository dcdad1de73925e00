// The end of a simulation as FMI 2.0 has it (4.2.3) and what may be set
// before initialization (3.2.3), on the stair fixture (tests/import/
// fixtures/stair.c): a co-simulation-only FMU whose counter goes up every
// second, that asks to end the simulation at endTime = 10 s (fmi2Discard
// with fmi2Terminated) and discards every step from discardTime on.
#include "fmusimTest.hpp"

namespace {

using namespace harness;

TEST(FmusimEnd, RunStopsCleanlyWhenTheFmuAsksToTerminate)
{
    // DefaultExperiment: 0 to 20 s in steps of 0.2 s; the stair ends at 10 s
    const std::string out = scratch("stair.csv");
    const harness::Result r
        = fmusim("run " + fixture("stair") + " --output-file " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(contains(
        r.err,
        "ended the simulation at t = 10: fmi2DoStep at t = 10: the stair ends at t = 10"))
        << r.err;
    const harness::Table t = harness::readTable(out);
    ASSERT_EQ(t.rows.size(), 51u); // 0, 0.2, ..., 10: every completed step
    EXPECT_NEAR(t.rows.back()[0], 10.0, 1e-12);
    EXPECT_EQ(t.rows.back()[t.column("counter")], 11.0);
}

TEST(FmusimEnd, ADiscardedStepIsASimulationError)
{
    const std::string out = scratch("stairDiscard.csv");
    const harness::Result r
        = fmusim("run " + fixture("stair")
                 + " --set discardTime=3 --output-file " + out);
    EXPECT_EQ(r.exitCode, 5) << r.err;
    EXPECT_TRUE(contains(r.err, "discarded the step from t = 3 to 3.2"));
    EXPECT_TRUE(contains(
        r.err,
        "without asking to end the simulation: fmi2DoStep at t = 3: no step from t >= "
        "discardTime = 3"))
        << r.err;
    EXPECT_EQ(harness::readTable(out).rows.size(), 16u); // 0 to 3 s
}

TEST(FmusimEnd, AnOutputWithInitialExactMayBeSet)
{
    const harness::Result r
        = fmusim("run " + fixture("stair") + " --set counter=5 --stop-time 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const harness::Table t = harness::parseTable(r.out);
    EXPECT_EQ(t.rows.front()[t.column("counter")], 5.0);
    EXPECT_EQ(t.rows.back()[t.column("counter")], 6.0);
    // An output without a start value (initial="calculated") may not
    const harness::Result y
        = fmusim("run " + fixture("firstOrderLag") + " --set y=1");
    EXPECT_TRUE(failed(y, 2, "--set: variable 'y'"));
}

} // namespace

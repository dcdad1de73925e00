// `fmusim check` on the plain-C testSpring connector, on its defective
// variant, on an FMU that is not a connector, and on the project's connector
// FMUs when they are built.
#include "fmusimTest.hpp"

namespace {

using namespace harness;

// Every line of a passing check: PASS, or SKIP with a reason.
void expectAllPass(const harness::Result& r)
{
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_FALSE(contains(r.out, "FAIL")) << r.out;
    EXPECT_TRUE(contains(r.out, " passed, 0 failed\n")) << r.out;
}

TEST(FmusimCheck, TestSpringPassesEveryCheck)
{
    const harness::Result r = fmusim("check " + fixture("testSpring"));
    expectAllPass(r);
    for (const char* name :
         {"required-variables", "optional-variables", "units", "capabilities",
          "parameters", "initialization", "random-kinematics", "finite-outputs",
          "equal-and-opposite-forces", "zero-total-moment", "rest-load",
          "state-get-set", "repeatable-step", "state-serialize",
          "variable-step-size", "non-finite-inputs"})
        EXPECT_TRUE(contains(r.out, std::string("PASS ") + name + "\n"))
            << name << "\n"
            << r.out;
    EXPECT_TRUE(contains(r.out, "16 passed, 0 failed\n")) << r.out;
}

TEST(FmusimCheck, OtherSeedsPassToo)
{
    for (const char* seed : {"2", "12345"})
        expectAllPass(fmusim("check " + fixture("testSpring") + " --seed "
                             + seed + " --samples 50"));
}

TEST(FmusimCheck, UnbalancedConnectorFails)
{
    // B.F = -A.F / 2 and the force unit is kN: three checks must fail.
    const harness::Result r
        = fmusim("check " + fixture("testSpringUnbalanced"));
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "PASS required-variables\n")) << r.out;
    EXPECT_TRUE(
        contains(r.out, "FAIL units: A.F[1] has unit 'kN', expected 'N'"))
        << r.out;
    EXPECT_TRUE(contains(r.out, "FAIL equal-and-opposite-forces: A.F + B.F = "))
        << r.out;
    EXPECT_TRUE(contains(
        r.out, "FAIL zero-total-moment: total moment about the origin"))
        << r.out;
    EXPECT_TRUE(contains(r.out, "13 passed, 3 failed\n")) << r.out;
}

TEST(FmusimCheck, NonConnectorFailsTheInterface)
{
    const harness::Result r = fmusim("check " + fixture("firstOrderLag"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(contains(
        r.out, "FAIL required-variables: missing A.r[1]; missing A.r[2]"))
        << r.out;
    EXPECT_TRUE(contains(
        r.out, "SKIP probes: the required variables are not all declared"))
        << r.out;
}

TEST(FmusimCheck, Errors)
{
    EXPECT_EQ(fmusim("check " + fixture("notAZip")).exitCode, 3);
    // Cannot be instantiated: a load error (3), as for run, not a failed
    // check (1); the report still gives the reason.
    const harness::Result guid = fmusim("check " + fixture("guidMismatch"));
    EXPECT_EQ(guid.exitCode, 3) << guid.out << guid.err;
    const std::string reason = "fmi2Instantiate failed in FMU '"
        + fixture("guidMismatch") + "', instance 'check'";
    EXPECT_TRUE(contains(guid.err, "fmusim: cannot load the FMU: " + reason))
        << guid.err;
    EXPECT_TRUE(contains(guid.out, "FAIL initialization: " + reason))
        << guid.out;
    EXPECT_TRUE(contains(guid.out, "4 passed, 2 failed\n")) << guid.out;
    EXPECT_EQ(fmusim("check " + fixture("testSpring") + " --seed -1").exitCode,
              2);
    EXPECT_EQ(fmusim("check").exitCode, 2);
}

#ifdef CONNECTOR_FMU_DIR
TEST(FmusimCheckConnectors, LinearSpringPasses)
{
    expectAllPass(fmusim("check " CONNECTOR_FMU_DIR "/linearSpring.fmu"));
}

TEST(FmusimCheckConnectors, LinearDamperPasses)
{
    expectAllPass(fmusim("check " CONNECTOR_FMU_DIR "/linearDamper.fmu"));
}
#endif

} // namespace

// `fmusim run` on spring connector FMUs reproduces the analytic law
// T = k (L - L0), A.F = T e, B.F = -T e, for B moved along a table while A
// stays at the origin: testSpring always, linearSpring when it is built.
#include "fmusimHarness.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

class SpringLaw : public ::testing::TestWithParam<std::string> { };

TEST_P(SpringLaw, RunReproducesTheAnalyticLaw)
{
    const double k = 200, L0 = 1;
    const std::string in = harness::scratch("in.csv"),
                      out = harness::scratch("out.csv");
    // B.r = (x, 0.5, 0) with x from 0.2 to 3 m: compressed, at rest near
    // x = 0.866 m, stretched; A at the origin, both orientations the identity,
    // B.p at B's reference point (its start value is 1 m from it).
    harness::writeFile(in, "time,B.r[1],B.r[2]\n0,0.2,0.5\n1,3,0.5\n");
    const harness::Result r = harness::fmusim(
        "run " + GetParam()
        + " --set stiffness=200 --set restLength=1 --set B.p[1]=0 --input-file "
        + in + " --stop-time 1 --step-size 0.01 --output-file " + out
        + " --output-variables \"A.F[1],A.F[2],A.F[3],B.F[1],B.F[2],A.M[3],B.M[3],potentialEnergy\"");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const harness::Table t = harness::readTable(out);
    ASSERT_EQ(t.rows.size(), 101u);
    for (const std::vector<double>& row : t.rows) {
        const double x = 0.2 + 2.8 * row[0], y = 0.5;
        const double L = std::hypot(x, y), T = k * (L - L0);
        // The law evaluated in a different order: a few ulps of k L = 600 N.
        const double tol = 1e-12 * k * 3;
        EXPECT_NEAR(row[1], T * x / L, tol) << "t = " << row[0];
        EXPECT_NEAR(row[2], T * y / L, tol) << "t = " << row[0];
        EXPECT_EQ(row[3], 0.0);
        EXPECT_NEAR(row[4], -T * x / L, tol);
        EXPECT_NEAR(row[5], -T * y / L, tol);
        // Attachment points at the reference points: no moments.
        EXPECT_EQ(row[6], 0.0);
        EXPECT_EQ(row[7], 0.0);
        EXPECT_NEAR(row[8], 0.5 * k * (L - L0) * (L - L0), tol);
    }
}

std::vector<std::string> springFmus()
{
    std::vector<std::string> fmus {harness::fixture("testSpring")};
#ifdef CONNECTOR_FMU_DIR
    fmus.push_back(CONNECTOR_FMU_DIR "/linearSpring.fmu");
#endif
    return fmus;
}

#ifdef CONNECTOR_FMU_DIR
// A spring to the world as the README's (its B.p the anchor in global
// coordinates, A at the origin): fmusim's defaults for B are the world the
// bridge feeds, so the anchor is where B.p says, 2.0 and 3.0 FMU alike
// (B.r started at (1, 0, 0) before, the anchor 1 m off)
TEST(SpringToTheWorld, TheAnchorIsBpWithBAtItsStartValues)
{
    for (const char* fmu : {CONNECTOR_FMU_DIR "/linearSpring.fmu",
                            CONNECTOR_FMU_DIR "/fmi3/linearSpring.fmu"}) {
        const std::string out = harness::scratch("world.csv");
        const harness::Result r = harness::fmusim(
            std::string("run ") + fmu
            + " --set stiffness=100 --set restLength=0.35"
              " --set A.p[2]=-0.1 --set A.p[3]=0.25"
              " --set B.p[1]=0.5 --set B.p[2]=0 --set B.p[3]=0.35"
              " --stop-time 0.01 --step-size 0.01 --output-file "
            + out + " --output-variables \"length,tension,B.F[1],B.M[2]\"");
        ASSERT_EQ(r.exitCode, 0) << fmu << ": " << r.err;
        const harness::Table t = harness::readTable(out);
        const double L = std::sqrt(0.5 * 0.5 + 0.1 * 0.1 + 0.1 * 0.1);
        for (const double length : t.values("length")) {
            EXPECT_NEAR(length, L, 1e-15) << fmu;
        }
        // B's moment about the world's origin: B.p x B.F; B.F along
        // A.p - B.p = (-0.5, -0.1, -0.1)/L times the tension
        const std::vector<double> T = t.values("tension"),
                                  Fx = t.values("B.F[1]"),
                                  My = t.values("B.M[2]");
        for (std::size_t i = 0; i < T.size(); ++i) {
            const double Fz = Fx[i] * 0.1 / 0.5;
            EXPECT_NEAR(Fx[i], -0.5 / L * T[i], 1e-12) << fmu;
            EXPECT_NEAR(My[i], 0.35 * Fx[i] - 0.5 * Fz, 1e-12) << fmu;
        }
    }
}
#endif

INSTANTIATE_TEST_SUITE_P(Fmus, SpringLaw, ::testing::ValuesIn(springFmus()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param.find("linearSpring")
                                     != std::string::npos
                                 ? "linearSpring"
                                 : "testSpring";
                         });

} // namespace

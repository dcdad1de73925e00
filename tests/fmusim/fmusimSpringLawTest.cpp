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
    // x = 0.866 m, stretched; A at the origin, both orientations the identity.
    harness::writeFile(in, "time,B.r[1],B.r[2]\n0,0.2,0.5\n1,3,0.5\n");
    const harness::Result r = harness::fmusim(
        "run " + GetParam()
        + " --set stiffness=200 --set restLength=1 --input-file " + in
        + " --stop-time 1 --step-size 0.01 --output-file " + out
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

INSTANTIATE_TEST_SUITE_P(Fmus, SpringLaw, ::testing::ValuesIn(springFmus()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param.find("linearSpring")
                                     != std::string::npos
                                 ? "linearSpring"
                                 : "testSpring";
                         });

} // namespace

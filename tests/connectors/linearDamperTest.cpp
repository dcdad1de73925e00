// connectors::LinearDamper against analytic values, balance laws, errors
// and the zero-length limit.
#include <gtest/gtest.h>

#include <limits>

#include "LawTestSupport.hpp"
#include "common/ConnectorError.hpp"
#include "linearDamper/LinearDamper.hpp"

namespace {

using namespace lawTest;
using connectors::LinearDamper;
using connectors::LinearDamperParameters;
using connectors::ParameterError;

LinearDamperParameters damperParameters(double c,
                                        const Vector3& pA = Vector3::Zero(),
                                        const Vector3& pB = Vector3::Zero())
{
    return {pA, pB, c}; // in the order of the members
}

TEST(LinearDamper, AnalyticRotatedBodies)
{
    // A at the origin turned 90 deg about z, A.p = (1,0,0): arm (0,1,0),
    // P = (0,1,0); A spins at 1 rad/s about z: v_P = (0,0,1) x (0,1,0) =
    // (-1,0,0). B at (0,4,4), B.p = 0, v_B = (2,3,-1):
    // p_PQ = (0,3,4), L = 5, e = (0,0.6,0.8), v_rel = (2,3,-1) - (-1,0,0) =
    // (3,3,-1), dL/dt = 1.8 - 0.8 = 1, c = 6: T = 6 N, f_A = (0,3.6,4.8), m_A =
    // (0,1,0) x f_A = (4.8,0,0), D = 6 W.
    const LinearDamper damper(damperParameters(6.0, Vector3(1, 0, 0)));
    const BodyKinematics A
        = body(Vector3::Zero(), rotation(EIGEN_PI / 2, Vector3::UnitZ()),
               Vector3::Zero(), Vector3(0, 0, 1));
    const BodyKinematics B
        = body(Vector3(0, 4, 4), Matrix3::Identity(), Vector3(2, 3, -1));
    const connectors::ConnectorResult r = damper.evaluate(A, B);
    // Tolerance: cos(pi/2) ~ 6e-17 in R_A perturbs the arm by ~1e-16 m;
    // with O(10) values the error is ~1e-15. 1e-12 leaves a wide margin.
    const double tol = 1e-12;
    EXPECT_NEAR(r.length, 5.0, tol);
    EXPECT_NEAR(r.lengthRate, 1.0, tol);
    EXPECT_NEAR(r.tension, 6.0, tol);
    expectVectorNear(r.A.f_W, Vector3(0, 3.6, 4.8), tol);
    expectVectorNear(r.B.f_W, Vector3(0, -3.6, -4.8), tol);
    expectVectorNear(r.A.m_Ko_W, Vector3(4.8, 0, 0), tol);
    expectVectorNear(r.B.m_Ko_W, Vector3::Zero(), tol);
    EXPECT_NEAR(r.dissipatedPower, 6.0, tol);
    EXPECT_EQ(r.potentialEnergy, 0.0);
}

TEST(LinearDamper, MotionAcrossTheAxisGivesNoForce)
{
    // B circles around A at fixed distance: v_rel is normal to the axis.
    const LinearDamper damper(damperParameters(50.0));
    const connectors::ConnectorResult r = damper.evaluate(
        body(Vector3::Zero()),
        body(Vector3(2, 0, 0), Matrix3::Identity(), Vector3(0, 3, -1)));
    EXPECT_EQ(r.lengthRate, 0.0); // exact: e = (1,0,0)
    EXPECT_EQ(r.A.f_W, Vector3::Zero());
    EXPECT_EQ(r.dissipatedPower, 0.0);
}

TEST(LinearDamper, DissipatesAndBalances)
{
    // Random geometries and motions: D = c (dL/dt)^2 >= 0, the power into
    // the bodies is exactly -D, forces are equal and opposite and the total
    // moment about any point is zero.
    std::mt19937 rng(2024);
    const LinearDamper damper(damperParameters(35.0, Vector3(0.4, 0.1, -0.2),
                                               Vector3(0.0, 0.3, 0.3)));
    for (int i = 0; i < 500; ++i) {
        const BodyKinematics A = randomBody(rng);
        const BodyKinematics B = randomBody(rng);
        const connectors::ConnectorResult r = damper.evaluate(A, B);
        EXPECT_GE(r.dissipatedPower, 0.0);
        // Tolerance: powers up to ~1e4 W, round-off ~1e-16 relative.
        EXPECT_NEAR(powerIntoBodies(r, A, B), -r.dissipatedPower, 1e-9);
        EXPECT_EQ(r.A.f_W + r.B.f_W, Vector3::Zero());
        // Tolerance: arms of O(4) m times forces up to ~1e3 N: ~1e-12 N.m.
        expectVectorNear(totalMomentAboutOrigin(r, A, B), Vector3::Zero(),
                         1e-9);
    }
}

TEST(LinearDamper, ZeroLengthGivesZeroForce)
{
    const LinearDamper damper(damperParameters(10.0));
    for (const double d : {0.0, 4e-13}) {
        const connectors::ConnectorResult r = damper.evaluate(
            body(Vector3(1, 1, 1)),
            body(Vector3(1 + d, 1, 1), Matrix3::Identity(), Vector3(5, -2, 1)));
        expectAllFinite(r);
        EXPECT_EQ(r.A.f_W, Vector3::Zero());
        EXPECT_EQ(r.lengthRate, 0.0);
        EXPECT_EQ(r.dissipatedPower, 0.0);
    }
}

TEST(LinearDamperErrors, Messages)
{
    expectThrowWithMessage<ParameterError>(
        [] { LinearDamper d(damperParameters(-2.0)); },
        "linearDamper: parameter damping = -2 N.s/m is out of range "
        "(allowed: finite and >= 0)");
    expectThrowWithMessage<ParameterError>(
        [] {
            LinearDamper d(damperParameters(
                1.0, Vector3(0, 0, std::numeric_limits<double>::infinity())));
        },
        "linearDamper: parameter A.p[3] = inf m is out of range (allowed: "
        "finite)");
    expectNanInputRefused(LinearDamper(damperParameters(1.0)),
                          &BodyKinematics::v_WKo_W, 1,
                          "linearDamper: input B.v[2] = nan is not finite");
}

} // namespace

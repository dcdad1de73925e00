// connectors::TranslationalDamper against analytic values (OpenFOAM's
// linearDamper restraint among them), balance laws, errors and the
// zero-length limit.
#include <gtest/gtest.h>

#include <limits>

#include "LawTestSupport.hpp"
#include "common/ConnectorError.hpp"
#include "translationalDamper/TranslationalDamper.hpp"

namespace {

using namespace lawTest;
using connectors::ParameterError;
using connectors::TranslationalDamper;
using connectors::TranslationalDamperParameters;

TranslationalDamperParameters
damperParameters(double c, const Vector3& pA = Vector3::Zero(),
                 const Vector3& pB = Vector3::Zero())
{
    return {pA, pB, c}; // in the order of the members
}

TEST(TranslationalDamper, AnalyticRotatedBodies)
{
    // A at the origin turned 90 deg about z, A.p = (1,0,0): arm (0,1,0),
    // P = (0,1,0); A spins at 1 rad/s about z: v_P = (0,0,1) x (0,1,0) =
    // (-1,0,0). B at (0,4,4), B.p = 0, v_B = (2,3,-1), spinning at
    // (1,0,0) rad/s: B's point at P moves at (2,3,-1) + (1,0,0) x
    // (0,-3,-4) = (2,7,-4), v_rel = (3,7,-4), c = 6: f_A = (18,42,-24),
    // f_B = -f_A at P, m_A = (0,1,0) x f_A = (-24,0,-18),
    // m_B = (0,-3,-4) x (-18,-42,24) = (-240,72,-54);
    // Q = (0,4,4), p_PQ = (0,3,4), L = 5, e = (0,0.6,0.8),
    // v_Q - v_P = (2,3,-1) - (-1,0,0) = (3,3,-1): dL/dt = 1.8 - 0.8 = 1,
    // T = f_A . e = 25.2 - 19.2 = 6 N, D = c |v_rel|^2 = 6 * 74 = 444 W.
    const TranslationalDamper damper(damperParameters(6.0, Vector3(1, 0, 0)));
    const BodyKinematics A
        = body(Vector3::Zero(), rotation(EIGEN_PI / 2, Vector3::UnitZ()),
               Vector3::Zero(), Vector3(0, 0, 1));
    const BodyKinematics B = body(Vector3(0, 4, 4), Matrix3::Identity(),
                                  Vector3(2, 3, -1), Vector3(1, 0, 0));
    const connectors::ConnectorResult r = damper.evaluate(A, B);
    // Tolerance: cos(pi/2) ~ 6e-17 in R_A perturbs the arm by ~1e-16 m;
    // with values up to ~400 the error is ~1e-13. 1e-11 leaves a margin.
    const double tol = 1e-11;
    EXPECT_NEAR(r.length, 5.0, tol);
    EXPECT_NEAR(r.lengthRate, 1.0, tol);
    EXPECT_NEAR(r.tension, 6.0, tol);
    expectVectorNear(r.A.f_W, Vector3(18, 42, -24), tol);
    expectVectorNear(r.B.f_W, Vector3(-18, -42, 24), tol);
    expectVectorNear(r.A.m_Ko_W, Vector3(-24, 0, -18), tol);
    expectVectorNear(r.B.m_Ko_W, Vector3(-240, 72, -54), tol);
    EXPECT_NEAR(r.dissipatedPower, 444.0, tol);
    EXPECT_EQ(r.potentialEnergy, 0.0);
}

TEST(TranslationalDamper, OpenFoamLinearDamperToTheWorld)
{
    // OpenFOAM's linearDamper restraint: F = -coeff v at the body's
    // reference point, no moment. A.p = 0, B the fixed world (at rest,
    // identity) with its anchor anywhere: the force on A is -c v_A,
    // whatever the body's rotation and spin.
    const Vector3 anchor(3, -2, 7);
    const TranslationalDamper damper(
        damperParameters(40.0, Vector3::Zero(), anchor));
    const BodyKinematics A
        = body(Vector3(0.5, 0.45, 0.1), rotation(0.3, Vector3(1, 2, 3)),
               Vector3(0.2, -0.7, 0.05), Vector3(0.4, -1, 2));
    const connectors::ConnectorResult r
        = damper.evaluate(A, body(Vector3::Zero()));
    // Tolerance: products of O(10) values, round-off ~1e-15.
    expectVectorNear(r.A.f_W, -40.0 * A.v_WKo_W, 1e-12);
    expectVectorNear(r.A.m_Ko_W, Vector3::Zero(), 1e-12);
    EXPECT_NEAR(r.dissipatedPower, 40.0 * A.v_WKo_W.squaredNorm(), 1e-12);
}

TEST(TranslationalDamper, MotionAcrossTheAxisIsDamped)
{
    // Unlike linearDamper: B moving across the line P-Q at fixed distance
    // is damped in full, with no tension.
    const TranslationalDamper damper(damperParameters(50.0));
    const connectors::ConnectorResult r = damper.evaluate(
        body(Vector3::Zero()),
        body(Vector3(2, 0, 0), Matrix3::Identity(), Vector3(0, 3, -1)));
    EXPECT_EQ(r.lengthRate, 0.0); // exact: e = (1,0,0)
    EXPECT_EQ(r.tension, 0.0);
    EXPECT_EQ(r.A.f_W, Vector3(0, 150, -50)); // exact products
    EXPECT_EQ(r.dissipatedPower, 500.0);
}

TEST(TranslationalDamper, DissipatesAndBalances)
{
    // Random geometries and motions: D = c |v_rel|^2 >= 0, the power into
    // the bodies is exactly -D, forces are equal and opposite and, both
    // acting at P, have no total moment about any point.
    std::mt19937 rng(2024);
    const TranslationalDamper damper(damperParameters(
        35.0, Vector3(0.4, 0.1, -0.2), Vector3(0.0, 0.3, 0.3)));
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

TEST(TranslationalDamper, ZeroLengthKeepsTheForce)
{
    const TranslationalDamper damper(damperParameters(10.0));
    for (const double d : {0.0, 4e-13}) {
        const connectors::ConnectorResult r = damper.evaluate(
            body(Vector3(1, 1, 1)),
            body(Vector3(1 + d, 1, 1), Matrix3::Identity(), Vector3(5, -2, 1)));
        expectAllFinite(r);
        EXPECT_EQ(r.A.f_W, Vector3(50, -20, 10)); // exact products
        EXPECT_EQ(r.lengthRate, 0.0);
        EXPECT_EQ(r.tension, 0.0);
        EXPECT_EQ(r.dissipatedPower, 300.0);
    }
}

TEST(TranslationalDamperErrors, Messages)
{
    expectThrowWithMessage<ParameterError>(
        [] { TranslationalDamper d(damperParameters(-2.0)); },
        "translationalDamper: parameter damping = -2 N.s/m is out of range "
        "(allowed: finite and >= 0)");
    expectThrowWithMessage<ParameterError>(
        [] {
            TranslationalDamper d(damperParameters(
                1.0, Vector3(0, 0, std::numeric_limits<double>::infinity())));
        },
        "translationalDamper: parameter A.p[3] = inf m is out of range "
        "(allowed: finite)");
    expectNanInputRefused(
        TranslationalDamper(damperParameters(1.0)), &BodyKinematics::v_WKo_W, 1,
        "translationalDamper: input B.v[2] = nan is not finite");
}

} // namespace

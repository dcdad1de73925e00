// connectors::RotationalDamper against analytic values (OpenFOAM's
// sphericalAngularDamper restraint among them), balance laws and errors.
#include <gtest/gtest.h>

#include <limits>

#include "LawTestSupport.hpp"
#include "common/ConnectorError.hpp"
#include "rotationalDamper/RotationalDamper.hpp"

namespace {

using namespace lawTest;
using connectors::ParameterError;
using connectors::RotationalDamper;
using connectors::RotationalDamperParameters;

RotationalDamperParameters damperParameters(double c,
                                            const Vector3& pA = Vector3::Zero(),
                                            const Vector3& pB = Vector3::Zero())
{
    return {pA, pB, c}; // in the order of the members
}

TEST(RotationalDamper, Analytic)
{
    // A at the origin spinning at (0,0,1) rad/s and moving at (1,0,0), B
    // at (0,3,4) spinning at (2,1,-1) and moving at (0,6,8): w_rel =
    // (2,1,-2), c = 4: m_A = (8,4,-8), m_B = -m_A, no forces, D = 4 * 9 =
    // 36 W; length 5, e = (0,0.6,0.8), dL/dt = e . ((0,6,8) - (1,0,0)) = 10.
    const RotationalDamper damper(damperParameters(4.0));
    const BodyKinematics A = body(Vector3::Zero(), Matrix3::Identity(),
                                  Vector3(1, 0, 0), Vector3(0, 0, 1));
    const BodyKinematics B = body(Vector3(0, 3, 4), Matrix3::Identity(),
                                  Vector3(0, 6, 8), Vector3(2, 1, -1));
    const connectors::ConnectorResult r = damper.evaluate(A, B);
    // Tolerance: products and sums of small integers are exact; the length
    // and its rate go through a square root and a division: 1e-14.
    expectVectorNear(r.A.m_Ko_W, Vector3(8, 4, -8), 1e-14);
    expectVectorNear(r.B.m_Ko_W, Vector3(-8, -4, 8), 1e-14);
    EXPECT_EQ(r.A.f_W, Vector3::Zero());
    EXPECT_EQ(r.B.f_W, Vector3::Zero());
    EXPECT_NEAR(r.length, 5.0, 1e-14);
    EXPECT_NEAR(r.lengthRate, 10.0, 1e-14);
    EXPECT_EQ(r.tension, 0.0);
    EXPECT_EQ(r.potentialEnergy, 0.0);
    EXPECT_NEAR(r.dissipatedPower, 36.0, 1e-14);
}

TEST(RotationalDamper, OpenFoamSphericalAngularDamperToTheWorld)
{
    // OpenFOAM's sphericalAngularDamper: M = -coeff omega, no force,
    // whatever the body's position, orientation and velocity; B the fixed
    // world at rest.
    const RotationalDamper damper(
        damperParameters(2.5, Vector3(0.1, 0.2, 0.3), Vector3(-1, 0, 2)));
    const BodyKinematics A
        = body(Vector3(0.5, 0.45, 0.1), rotation(0.7, Vector3(1, -2, 0.5)),
               Vector3(0.3, 0.1, -0.4), Vector3(0.4, -1, 2));
    const connectors::ConnectorResult r
        = damper.evaluate(A, body(Vector3::Zero()));
    // Tolerance: one product of O(1) values, round-off ~1e-16.
    expectVectorNear(r.A.m_Ko_W, -2.5 * A.w_WK_W, 1e-14);
    EXPECT_EQ(r.A.f_W, Vector3::Zero());
}

TEST(RotationalDamper, DissipatesAndBalances)
{
    // Random motions: D = c |w_rel|^2 >= 0, the power into the bodies is
    // exactly -D, no forces and no total moment about any point.
    std::mt19937 rng(2025);
    const RotationalDamper damper(
        damperParameters(7.0, Vector3(0.4, 0.1, -0.2), Vector3(0.0, 0.3, 0.3)));
    for (int i = 0; i < 500; ++i) {
        const BodyKinematics A = randomBody(rng);
        const BodyKinematics B = randomBody(rng);
        const connectors::ConnectorResult r = damper.evaluate(A, B);
        EXPECT_GE(r.dissipatedPower, 0.0);
        // Tolerance: powers up to ~1e2 W, round-off ~1e-16 relative.
        EXPECT_NEAR(powerIntoBodies(r, A, B), -r.dissipatedPower, 1e-11);
        EXPECT_EQ(r.A.m_Ko_W + r.B.m_Ko_W, Vector3::Zero());
        expectVectorNear(totalMomentAboutOrigin(r, A, B), Vector3::Zero(),
                         1e-12);
    }
}

TEST(RotationalDamperErrors, Messages)
{
    expectThrowWithMessage<ParameterError>(
        [] { RotationalDamper d(damperParameters(-2.0)); },
        "rotationalDamper: parameter damping = -2 N.m.s/rad is out of range "
        "(allowed: finite and >= 0)");
    expectThrowWithMessage<ParameterError>(
        [] {
            RotationalDamper d(damperParameters(
                1.0, Vector3::Zero(),
                Vector3(std::numeric_limits<double>::quiet_NaN(), 0, 0)));
        },
        "rotationalDamper: parameter B.p[1] = nan m is out of range (allowed: "
        "finite)");
    expectNanInputRefused(RotationalDamper(damperParameters(1.0)),
                          &BodyKinematics::w_WK_W, 2,
                          "rotationalDamper: input B.omega[3] = nan is not "
                          "finite");
}

} // namespace

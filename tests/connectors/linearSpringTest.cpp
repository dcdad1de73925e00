// connectors::LinearSpring against analytic values and balance laws.
#include <gtest/gtest.h>

#include <cmath>

#include "LawTestSupport.hpp"
#include "linearSpring/LinearSpring.hpp"

namespace {

using namespace lawTest;
using connectors::LinearSpring;
using connectors::LinearSpringParameters;

LinearSpringParameters springParameters(double k, double L0, double c,
                                        const Vector3& pA = Vector3::Zero(),
                                        const Vector3& pB = Vector3::Zero())
{
    return {pA, pB, k, L0, c}; // in the order of the members
}

TEST(LinearSpring, ZeroForceAtRestLength)
{
    // Rotated bodies, attachment points off the reference points, P and Q
    // placed exactly 1.5 m apart along a skew direction.
    const LinearSpring spring(springParameters(
        200.0, 1.5, 0.0, Vector3(0.1, -0.2, 0.3), Vector3(-0.4, 0.0, 0.2)));
    const BodyKinematics A
        = body(Vector3(1, 2, 3), rotation(0.7, Vector3(1, 1, 0)));
    const Vector3 p_WP = A.p_WKo_W + A.R_WK * spring.parameters().p_AoP_A;
    const Vector3 e = Vector3(2, -1, 2) / 3.0;
    const Matrix3 R_B = rotation(-1.1, Vector3(0, 1, 1));
    const Vector3 p_WQ = p_WP + 1.5 * e;
    const BodyKinematics B
        = body(p_WQ - R_B * spring.parameters().p_BoQ_B, R_B);
    const ConnectorResult r = spring.evaluate(A, B);
    // Tolerance: the length is rebuilt from sums of O(1) m coordinates, so
    // L - L0 is exact only to a few ulps of 1.5 (~1e-15 m); k = 200 N/m
    // gives forces of ~1e-13 N. 1e-11 N leaves a margin of 100.
    EXPECT_NEAR(r.length, 1.5, 1e-14);
    expectVectorNear(r.A.f_W, Vector3::Zero(), 1e-11);
    expectVectorNear(r.B.f_W, Vector3::Zero(), 1e-11);
    expectVectorNear(r.A.m_Ko_W, Vector3::Zero(), 1e-11);
    EXPECT_NEAR(r.tension, 0.0, 1e-11);
    EXPECT_NEAR(r.potentialEnergy, 0.0, 1e-24);
}

TEST(LinearSpring, StretchedAlongX)
{
    // k = 100 N/m, L0 = 1.5 m, L = 2 m: T = 50 N, V = 12.5 J. Every input is
    // exactly representable, so the values are exact (tolerance 0).
    const LinearSpring spring(springParameters(100.0, 1.5, 0.0));
    const ConnectorResult r
        = spring.evaluate(body(Vector3::Zero()), body(Vector3(2, 0, 0)));
    EXPECT_EQ(r.A.f_W, Vector3(50, 0, 0));
    EXPECT_EQ(r.B.f_W, Vector3(-50, 0, 0));
    EXPECT_EQ(r.A.m_Ko_W, Vector3::Zero());
    EXPECT_EQ(r.tension, 50.0);
    EXPECT_EQ(r.length, 2.0);
    EXPECT_EQ(r.potentialEnergy, 12.5);
    EXPECT_EQ(r.dissipatedPower, 0.0);
}

TEST(LinearSpring, RotatedBodiesWithOffsetAttachments)
{
    // A at (1,2,3) turned 90 deg about z: A.p = (1,0,0) has the lever arm
    // (0,1,0), P = (1,3,3). B at (1,6,8) turned 90 deg about x:
    // B.p = (0,-1,0) has the lever arm (0,0,-1), Q = (1,6,7).
    // p_PQ = (0,3,4), L = 5 m, e = (0,0.6,0.8); k = 10, L0 = 3: T = 20 N,
    // f_A = (0,12,16), f_B = -f_A, m_A = (0,1,0) x f_A = (16,0,0),
    // m_B = (0,0,-1) x f_B = (-12,0,0), V = 20 J.
    const LinearSpring spring(
        springParameters(10.0, 3.0, 0.0, Vector3(1, 0, 0), Vector3(0, -1, 0)));
    const BodyKinematics A
        = body(Vector3(1, 2, 3), rotation(EIGEN_PI / 2, Vector3::UnitZ()));
    const BodyKinematics B
        = body(Vector3(1, 6, 8), rotation(EIGEN_PI / 2, Vector3::UnitX()));
    const ConnectorResult r = spring.evaluate(A, B);
    // Tolerance: cos(pi/2) = 6e-17 instead of 0 in the rotation matrices
    // perturbs the lever arms by ~1e-16 m; times forces of 20 N and a few
    // roundings this is ~1e-14. 1e-12 (N, N.m, m, J) is well above it.
    const double tol = 1e-12;
    EXPECT_NEAR(r.length, 5.0, tol);
    EXPECT_NEAR(r.tension, 20.0, tol);
    expectVectorNear(r.A.f_W, Vector3(0, 12, 16), tol);
    expectVectorNear(r.B.f_W, Vector3(0, -12, -16), tol);
    expectVectorNear(r.A.m_Ko_W, Vector3(16, 0, 0), tol);
    expectVectorNear(r.B.m_Ko_W, Vector3(-12, 0, 0), tol);
    EXPECT_NEAR(r.potentialEnergy, 20.0, tol);
}

TEST(LinearSpring, DampingUsesTheVelocityOfTheAttachmentPoints)
{
    // P = A.p = (0,1,0) on A at rest at the origin spinning at 2 rad/s
    // about z: v_P = (0,0,2) x (0,1,0) = (-2,0,0). Q = B.r = (3,1,0) moving
    // at (1,5,0). e = (1,0,0), dL/dt = (1 - -2) = 3 m/s (the y velocity is
    // across the axis). k = 10, L0 = 1, c = 4: T = 10*2 + 4*3 = 32 N,
    // m_A = (0,1,0) x (32,0,0) = (0,0,-32), D = 4 * 9 = 36 W.
    const LinearSpring spring(
        springParameters(10.0, 1.0, 4.0, Vector3(0, 1, 0)));
    const BodyKinematics A = body(Vector3::Zero(), Matrix3::Identity(),
                                  Vector3::Zero(), Vector3(0, 0, 2));
    const BodyKinematics B
        = body(Vector3(3, 1, 0), Matrix3::Identity(), Vector3(1, 5, 0));
    const ConnectorResult r = spring.evaluate(A, B);
    // Exact inputs, exact arithmetic: tolerance 0.
    EXPECT_EQ(r.lengthRate, 3.0);
    EXPECT_EQ(r.tension, 32.0);
    EXPECT_EQ(r.A.f_W, Vector3(32, 0, 0));
    EXPECT_EQ(r.A.m_Ko_W, Vector3(0, 0, -32));
    EXPECT_EQ(r.dissipatedPower, 36.0);
    EXPECT_EQ(r.potentialEnergy, 20.0); // 10/2 * (3 - 1)^2
}

TEST(LinearSpring, EqualAndOppositeForcesAndZeroTotalMoment)
{
    std::mt19937 rng(12345);
    const LinearSpring spring(springParameters(
        350.0, 0.8, 12.0, Vector3(0.3, -0.2, 0.5), Vector3(-0.1, 0.4, 0.2)));
    for (int i = 0; i < 200; ++i) {
        const BodyKinematics A = randomBody(rng);
        const BodyKinematics B = randomBody(rng);
        const ConnectorResult r = spring.evaluate(A, B);
        EXPECT_EQ(r.A.f_W + r.B.f_W, Vector3::Zero());
        // Tolerance: moments are sums of products of O(4) m arms and
        // forces up to ~3e3 N; round-off ~1e-16 * 4 * 3e3 * a few terms
        // ~1e-11 N.m. 1e-9 N.m leaves a margin of 100.
        expectVectorNear(totalMomentAboutOrigin(r, A, B), Vector3::Zero(),
                         1e-9);
    }
}

TEST(LinearSpring, PowerBalance)
{
    // Power into the bodies = -dV/dt - D with dV/dt = k (L - L0) dL/dt.
    std::mt19937 rng(777);
    const double k = 120.0, L0 = 0.6, c = 7.0;
    const LinearSpring spring(springParameters(
        k, L0, c, Vector3(0.2, 0.1, -0.3), Vector3(0.0, -0.5, 0.1)));
    for (int i = 0; i < 200; ++i) {
        const BodyKinematics A = randomBody(rng);
        const BodyKinematics B = randomBody(rng);
        const ConnectorResult r = spring.evaluate(A, B);
        const double dVdt = k * (r.length - L0) * r.lengthRate;
        EXPECT_GE(r.dissipatedPower, 0.0);
        // Tolerance: terms up to ~1e4 W, round-off ~1e-16 relative: 1e-9 W.
        EXPECT_NEAR(powerIntoBodies(r, A, B), -dVdt - r.dissipatedPower, 1e-9);
    }
}

//- Both bodies move and rotate along smooth paths (fixed rotation axes, so
//  that omega = dtheta/dt * axis exactly)
struct Path {
    BodyKinematics A(double t) const
    {
        const Vector3 axis = Vector3(1, 2, 2) / 3.0;
        return body(Vector3(0.3 * std::sin(t), 0.2 * t, 0.0),
                    rotation(0.5 * t, axis),
                    Vector3(0.3 * std::cos(t), 0.2, 0.0), 0.5 * axis);
    }
    BodyKinematics B(double t) const
    {
        const Vector3 axis = Vector3(0, 0.6, 0.8);
        return body(Vector3(2.0 + 0.5 * std::cos(2 * t), 1.0, 0.4 * t),
                    rotation(0.8 * std::sin(t), axis),
                    Vector3(-std::sin(2 * t), 0.0, 0.4),
                    0.8 * std::cos(t) * axis);
    }
};

TEST(LinearSpring, WorkAlongAPathMatchesEnergy)
{
    // Work done by the connector on the bodies over [0, T] equals
    // -(V(T) - V(0)) - (energy dissipated), integrated with Simpson's rule.
    const Path path;
    for (const double c : {0.0, 3.0}) {
        const LinearSpring spring(springParameters(
            50.0, 1.2, c, Vector3(0.2, -0.1, 0.3), Vector3(-0.3, 0.2, 0.1)));
        const int n = 2000;
        const double T = 2.0, h = T / n;
        double work = 0.0, dissipated = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double t = i * h;
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            const ConnectorResult r = spring.evaluate(path.A(t), path.B(t));
            work += w * h / 3.0 * powerIntoBodies(r, path.A(t), path.B(t));
            dissipated += w * h / 3.0 * r.dissipatedPower;
        }
        const double V0 = spring.evaluate(path.A(0), path.B(0)).potentialEnergy;
        const double VT = spring.evaluate(path.A(T), path.B(T)).potentialEnergy;
        // Tolerance: Simpson's error is T h^4 max|P''''| / 180 with
        // h = 1e-3 s and |P''''| of order 1e3 W/s^4 (smooth sines, k = 50):
        // ~1e-11 J. 1e-8 J is far above it and far below the J-sized
        // energies compared (V0, VT and the work are 1 to 30 J).
        EXPECT_GT(std::abs(VT - V0), 0.1) << "the path must change the energy";
        EXPECT_NEAR(work, -(VT - V0) - dissipated, 1e-8) << "damping " << c;
        if (c > 0.0) {
            EXPECT_GT(dissipated, 0.0);
        }
    }
}

} // namespace

// connectors::SphericalAngularSpring against analytic values of OpenFOAM's
// sixDoF sphericalAngularSpring, the same relative to a turned and spinning
// body B, the power balance where it holds (turns about the reference axes;
// small angles, within the bound of the non-conservative part), the work
// around a closed loop of rotations, and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "LawTestSupport.hpp"
#include "common/ConnectorError.hpp"
#include "sphericalAngularSpring/SphericalAngularSpring.hpp"

namespace {

using namespace lawTest;
using connectors::ParameterError;
using connectors::SphericalAngularSpring;
using connectors::SphericalAngularSpringParameters;

SphericalAngularSpringParameters
springParameters(double k, double c, const Matrix3& Q0 = Matrix3::Identity())
{
    SphericalAngularSpringParameters p;
    p.R_BA0 = Q0;
    p.stiffness = k;
    p.damping = c;
    return p;
}

TEST(SphericalAngularSpring, AnalyticTurnAboutAReferenceAxis)
{
    // Reference the identity, A turned 0.3 rad about x and turning at
    // 2 rad/s about x, s = sin 0.3, co = cos 0.3. OpenFOAM's three terms:
    // axis x: e_y x (R e_y = (0, co, s), nothing along x) = (s, 0, 0);
    // axis y: e_z x (R e_z = (0, -s, co) less (0, -s, 0)) = e_z x co e_z = 0;
    // axis z: e_x x (R e_x = e_x) = 0. k = 5, c = 0.5: M_A = -(5 s + 1) e_x,
    // energy 5 (1 - co), dissipated 0.5 * 4 = 2.
    const SphericalAngularSpring spring(springParameters(5.0, 0.5));
    const BodyKinematics A
        = body(Vector3(0.5, 0.45, 0.1), rotation(0.3, Vector3::UnitX()),
               Vector3(1, 2, 3), Vector3(2, 0, 0));
    const connectors::ConnectorResult r
        = spring.evaluate(A, body(Vector3::Zero()));
    // Tolerance: sums of products of O(1) values, round-off ~1e-16.
    expectVectorNear(r.A.m_Ko_W, Vector3(-(5 * std::sin(0.3) + 1), 0, 0),
                     1e-14);
    expectVectorNear(r.B.m_Ko_W, -r.A.m_Ko_W, 0.0);
    EXPECT_EQ(r.A.f_W, Vector3::Zero());
    EXPECT_EQ(r.B.f_W, Vector3::Zero());
    EXPECT_EQ(r.tension, 0.0);
    EXPECT_NEAR(r.potentialEnergy, 5 * (1 - std::cos(0.3)), 1e-14);
    EXPECT_NEAR(r.dissipatedPower, 2.0, 1e-14);
}

TEST(SphericalAngularSpring, ThirdOfATurnIsNotTheGradient)
{
    // A turned 120 deg about (1,1,1): R e_x = e_y, R e_y = e_z, R e_z = e_x.
    // Axis x: e_y x e_z = e_x; axis y: e_z x e_x = e_y; axis z: e_x x e_y
    // = e_z: M_A = -k (1, 1, 1). The potential energy is k (1 - cos 120
    // deg) = 1.5 k, whose gradient alone would give -k sin(120 deg) n =
    // -k (1, 1, 1) / 2: the other half is the non-conservative part
    // -k (1 - cos 120 deg) (n_y n_z, n_z n_x, n_x n_y) = -k (1, 1, 1) / 2.
    const double k = 2.0;
    const SphericalAngularSpring spring(springParameters(k, 0.0));
    Matrix3 R;
    R << 0, 0, 1, 1, 0, 0, 0, 1, 0;
    const connectors::ConnectorResult r
        = spring.evaluate(body(Vector3::Zero(), R), body(Vector3(1, 0, 0)));
    // Tolerance: entries 0 and 1, every operation exact.
    expectVectorNear(r.A.m_Ko_W, -k * Vector3(1, 1, 1), 0.0);
    EXPECT_EQ(r.potentialEnergy, 1.5 * k);
    const Vector3 n = Vector3(1, 1, 1).normalized();
    const double theta = 2 * pi / 3;
    // Tolerance: sin, cos and a normalisation, ~1e-16 each.
    expectVectorNear(r.A.m_Ko_W,
                     -k * std::sin(theta) * n
                         - k * (1 - std::cos(theta)) * Vector3(1, 1, 1) / 3,
                     1e-15);
}

TEST(SphericalAngularSpring, AnEquilibriumAwayFromTheReference)
{
    // 120 deg about (-1, 1, 1): R e_y = -e_x, R e_z = e_y, R e_x = -e_z.
    // Each turned direction lies along the axis of its term and is
    // removed: axis x, -e_x less its part along x = 0; axis y, e_y less
    // e_y = 0; axis z, -e_z less -e_z = 0. No moment, though A is as far
    // from its reference as in ThirdOfATurnIsNotTheGradient (energy 1.5 k).
    Matrix3 R;
    R << 0, -1, 0, 0, 0, 1, -1, 0, 0;
    const SphericalAngularSpring spring(springParameters(2.0, 0.0));
    const connectors::ConnectorResult r
        = spring.evaluate(body(Vector3::Zero(), R), body(Vector3(1, 0, 0)));
    // Tolerance: entries 0 and 1, every operation exact.
    expectVectorNear(r.A.m_Ko_W, Vector3::Zero(), 0.0);
    EXPECT_EQ(r.potentialEnergy, 3.0);
}

TEST(SphericalAngularSpring, RelativeToBody)
{
    // Everything turned by G and B spinning; A 0.3 rad from its reference
    // Q0 about Q0's x axis and turning at 2 rad/s about it relative to B:
    // as AnalyticTurnAboutAReferenceAxis in Q0's frame, turned by G.
    const double k = 5.0, c = 0.5;
    const Matrix3 Q0 = rotation(0.5, Vector3(0, 1, 1));
    const SphericalAngularSpring spring(springParameters(k, c, Q0));
    const Matrix3 G = rotation(1.1, Vector3(1, -2, 0.5));
    const Vector3 wB(0.3, -0.7, 1.2);
    const BodyKinematics A
        = body(Vector3::Zero(), G * Q0 * rotation(0.3, Vector3::UnitX()),
               Vector3::Zero(), wB + G * Q0 * Vector3(2, 0, 0));
    const BodyKinematics B = body(Vector3(1, 2, 3), G, Vector3(0.1, 0, 0), wB);
    const connectors::ConnectorResult r = spring.evaluate(A, B);
    // Tolerance: products of O(1) rotations, round-off ~1e-15.
    expectVectorNear(r.A.m_Ko_W,
                     G * Q0 * Vector3(-(k * std::sin(0.3) + 2 * c), 0, 0),
                     1e-13);
    expectVectorNear(r.A.m_Ko_W + r.B.m_Ko_W, Vector3::Zero(), 0.0);
    EXPECT_NEAR(r.potentialEnergy, k * (1 - std::cos(0.3)), 1e-13);
    EXPECT_NEAR(r.dissipatedPower, c * 4, 1e-13);
}

TEST(SphericalAngularSpring, AtTheReferenceNoMoment)
{
    // A at its reference orientation relative to a turned B, both turning
    // together: no moment, no energy, no dissipation.
    const Matrix3 Q0 = rotation(0.8, Vector3(1, 2, -1));
    const SphericalAngularSpring spring(springParameters(5.0, 0.5, Q0));
    const Matrix3 G = rotation(-2.1, Vector3(0.2, 1, 0.4));
    const Vector3 w(0.4, -1, 2);
    const connectors::ConnectorResult r
        = spring.evaluate(body(Vector3(1, 0, 0), G * Q0, Vector3::Zero(), w),
                          body(Vector3::Zero(), G, Vector3::Zero(), w));
    // Tolerance: round-off of products of O(1) rotations, times k = 5.
    expectVectorNear(r.A.m_Ko_W, Vector3::Zero(), 1e-14);
    EXPECT_NEAR(r.potentialEnergy, 0.0, 1e-30);
    EXPECT_EQ(r.dissipatedPower, 0.0);
}

TEST(SphericalAngularSpring, PowerOfTurnsAboutTheReferenceAxes)
{
    // A turning about an axis of its reference frame at rate s from angle
    // phi: M_A = -(k sin phi + c s) a (the non-conservative part is zero),
    // E = k (1 - cos phi): the power into the bodies is -k sin(phi) s - c s^2
    // = -dE/dt - D, at every angle.
    const double k = 3.0, c = 0.25, s = 0.8;
    const Matrix3 Q0 = rotation(0.7, Vector3(-1, 0.5, 2));
    const SphericalAngularSpring spring(springParameters(k, c, Q0));
    for (int i = 0; i < 3; ++i) {
        const Vector3 a = Q0 * Vector3::Unit(i);
        for (const double phi : {-2.9, -1.0, -0.01, 0.2, 1.7, 3.0}) {
            const BodyKinematics A = body(
                Vector3::Zero(), rotation(phi, a) * Q0, Vector3::Zero(), s * a);
            const BodyKinematics B = body(Vector3::Zero());
            const connectors::ConnectorResult r = spring.evaluate(A, B);
            // Tolerance: O(1) rotations, round-off ~1e-15.
            EXPECT_NEAR(r.potentialEnergy, k * (1 - std::cos(phi)), 1e-14)
                << i << " " << phi;
            EXPECT_NEAR(powerIntoBodies(r, A, B),
                        -k * std::sin(phi) * s - c * s * s, 1e-14)
                << i << " " << phi;
        }
    }
}

TEST(SphericalAngularSpring, PowerBalanceWithinTheNonConservativeBound)
{
    // Random turns relative to a random B, up to 0.1 rad from the
    // reference, random relative spin: the power into the bodies differs
    // from -dE/dt - D by the power of the non-conservative part, at most
    // k (1 - cos theta) |w_rel| / sqrt(3) (theta^2/2 of the spring's
    // moment k theta, relative order theta / 3.5 at most).
    const double k = 4.0, c = 0.3;
    const Matrix3 Q0 = rotation(2.0, Vector3(0.3, -1, 0.2));
    const SphericalAngularSpring spring(springParameters(k, c, Q0));
    std::mt19937 rng(1912);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double largest = 0.0;
    for (int n = 0; n < 200; ++n) {
        const BodyKinematics B = randomBody(rng);
        const double theta = 0.1 * std::abs(u(rng));
        const Matrix3 R_WA
            = B.R_WK * rotation(theta, Vector3(u(rng), u(rng), u(rng))) * Q0;
        const Vector3 w_rel_W(u(rng), u(rng), u(rng));
        const BodyKinematics A
            = body(Vector3::Zero(), R_WA, Vector3::Zero(), B.w_WK_W + w_rel_W);
        const connectors::ConnectorResult r = spring.evaluate(A, B);
        // dE/dt by central differences over +-h, both bodies turned by
        // their angular velocities
        const double h = 1e-6;
        const auto energyAt = [&](double t) {
            return spring
                .evaluate(
                    body(Vector3::Zero(),
                         rotation(t * A.w_WK_W.norm(), A.w_WK_W) * R_WA),
                    body(Vector3::Zero(),
                         rotation(t * B.w_WK_W.norm(), B.w_WK_W) * B.R_WK))
                .potentialEnergy;
        };
        const double dEdt = (energyAt(h) - energyAt(-h)) / (2 * h);
        const double mismatch
            = powerIntoBodies(r, A, B) + dEdt + r.dissipatedPower;
        const double bound
            = k * (1 - std::cos(theta)) * w_rel_W.norm() / std::sqrt(3.0);
        // Tolerance: the central difference, round-off ~1e-16 / h = 1e-10.
        EXPECT_LE(std::abs(mismatch), bound + 1e-9) << n;
        largest = std::max(largest, std::abs(mismatch) / (bound + 1e-300));
    }
    // The bound is not loose: some state comes within a third of it.
    EXPECT_GT(largest, 0.33);
}

//- Work [J] of the spring on A (B the fixed world) over a turn by `angle`
//  about x, one by `angle` about A's own y and the shortest turn back to
//  where A started; midpoint rule, `steps` steps a turn.
double loopWork(const SphericalAngularSpring& spring, double angle, int steps)
{
    Matrix3 R = Matrix3::Identity();
    double work = 0.0;
    const auto turn = [&](const Vector3& axis, double by) {
        const double h = by / steps;
        for (int n = 0; n < steps; ++n) {
            const BodyKinematics A
                = body(Vector3::Zero(), rotation(h / 2, axis) * R,
                       Vector3::Zero(), axis.normalized());
            work += powerIntoBodies(spring.evaluate(A, body(Vector3::Zero())),
                                    A, body(Vector3::Zero()))
                * h;
            R = rotation(h, axis) * R;
        }
    };
    turn(Vector3::UnitX(), angle);
    turn(R * Vector3::UnitY(), angle); // about A's own y
    const Eigen::AngleAxisd back(R);
    turn(-back.axis(), back.angle());
    // Tolerance: round-off of 3 x steps rotations, ~1e-16 each.
    EXPECT_LT((R - Matrix3::Identity()).norm(), 1e-12);
    return work;
}

TEST(SphericalAngularSpring, WorkAroundAClosedLoopOfRotations)
{
    // 1.4 rad about x, 1.4 rad about A's y, the shortest turn back: A is
    // where it started, the potential energy too, but the moment has done
    // 0.0727 J of work (k = 1 N.m/rad; docs/convert.md); at 0.14 rad,
    // -4.7e-5 J, 0.5 % of the 0.0098 J the energy reaches in the first
    // turn.
    const SphericalAngularSpring spring(springParameters(1.0, 0.0));
    // Tolerance: the midpoint rule's error, O((angle / steps)^2) of the
    // work: 5.5e-9 J and 1.5e-12 J between 2000 and 4000 steps.
    EXPECT_NEAR(loopWork(spring, 1.4, 2000), 0.0726939, 1e-7);
    EXPECT_NEAR(loopWork(spring, 0.14, 2000), -4.71147e-5, 1e-10);
}

TEST(SphericalAngularSpringErrors, Messages)
{
    expectThrowWithMessage<ParameterError>(
        [] { SphericalAngularSpring s(springParameters(-1.0, 0.0)); },
        "sphericalAngularSpring: parameter stiffness = -1 N.m/rad is out of "
        "range (allowed: finite and >= 0)");
    expectThrowWithMessage<ParameterError>(
        [] { SphericalAngularSpring s(springParameters(1.0, -0.5)); },
        "sphericalAngularSpring: parameter damping = -0.5 N.m.s/rad is out of "
        "range (allowed: finite and >= 0)");
    expectThrowWithMessage<ParameterError>(
        [] {
            SphericalAngularSpringParameters p = springParameters(1.0, 0.0);
            p.R_BA0(2, 0) = std::numeric_limits<double>::quiet_NaN();
            SphericalAngularSpring s(p);
        },
        "sphericalAngularSpring: parameter referenceOrientation[3,1] = nan is "
        "out of range (allowed: finite)");
    expectThrowWithMessage<ParameterError>(
        [] {
            // A reflection passes (norm sqrt(3)), as in OpenFOAM; a
            // rotation scaled by 1.01 does not
            SphericalAngularSpring s(
                springParameters(1.0, 0.0, 1.01 * Matrix3::Identity()));
        },
        "sphericalAngularSpring: parameter referenceOrientation is not a "
        "rotation tensor: |referenceOrientation| - sqrt(3) = "
        "0.017320508075688856 (allowed: within 3.2e-08 of 0, as OpenFOAM "
        "reads it)");
    expectNanInputRefused(SphericalAngularSpring(springParameters(1.0, 0.0)),
                          &BodyKinematics::w_WK_W, 1,
                          "sphericalAngularSpring: input B.omega[2] = nan is "
                          "not finite");
}

} // namespace

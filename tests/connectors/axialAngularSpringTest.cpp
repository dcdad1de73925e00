// connectors::AxialAngularSpring against analytic values of OpenFOAM's
// sixDoF linearAxialAngularSpring, the same relative to a turned and
// spinning body B, the power balance of turns about the axis, and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "LawTestSupport.hpp"
#include "axialAngularSpring/AxialAngularSpring.hpp"
#include "common/ConnectorError.hpp"

namespace {

using namespace lawTest;
using connectors::AxialAngularSpring;
using connectors::AxialAngularSpringParameters;
using connectors::ParameterError;

AxialAngularSpringParameters springParameters(double k, double c,
                                              const Vector3& axis)
{
    AxialAngularSpringParameters p;
    p.axis_B = axis;
    p.stiffness = k;
    p.damping = c;
    return p;
}

TEST(AxialAngularSpring, AnalyticTurnAboutTheAxis)
{
    // Axis y (given as (0,2,0): normalised), reference the identity, A
    // turned 0.3 rad about y and turning at 2 rad/s. rotationTensor(e_x,
    // e_y) turns e_y onto -e_x: d = -e_x, u = -e_x, w = (-cos 0.3, 0,
    // sin 0.3): theta = 0.3, u x w = (0, sin 0.3, 0): a = e_y;
    // k = 5, c = 0.5: M_A = -(1.5 + 1) e_y, energy 5 * 0.09 / 2 = 0.225,
    // dissipated 0.5 * 4 = 2.
    const AxialAngularSpring spring(
        springParameters(5.0, 0.5, Vector3(0, 2, 0)));
    const BodyKinematics A
        = body(Vector3(0.5, 0.45, 0.1), rotation(0.3, Vector3::UnitY()),
               Vector3(1, 2, 3), Vector3(0, 2, 0));
    const connectors::ConnectorResult r
        = spring.evaluate(A, body(Vector3::Zero()));
    // Tolerance: acos near 0.3 and products of O(1) values: 1e-14.
    expectVectorNear(r.A.m_Ko_W, Vector3(0, -2.5, 0), 1e-14);
    expectVectorNear(r.B.m_Ko_W, Vector3(0, 2.5, 0), 1e-14);
    EXPECT_EQ(r.A.f_W, Vector3::Zero());
    EXPECT_EQ(r.tension, 0.0);
    EXPECT_NEAR(r.potentialEnergy, 0.225, 1e-14);
    EXPECT_NEAR(r.dissipatedPower, 2.0, 1e-14);
}

TEST(AxialAngularSpring, TurnedOtherWay)
{
    // The same turn the other way: the moment changes sign
    const AxialAngularSpring spring(
        springParameters(5.0, 0.0, Vector3::UnitY()));
    const connectors::ConnectorResult r = spring.evaluate(
        body(Vector3::Zero(), rotation(-0.3, Vector3::UnitY())),
        body(Vector3::Zero()));
    expectVectorNear(r.A.m_Ko_W, Vector3(0, 1.5, 0), 1e-14);
}

TEST(AxialAngularSpring, RelativeToBody)
{
    // Everything turned by G and B spinning: the moment turns with G,
    // the energy and the dissipation are the same.
    const AxialAngularSpring spring(
        springParameters(5.0, 0.5, Vector3::UnitY()));
    const Matrix3 G = rotation(1.1, Vector3(1, -2, 0.5));
    const Vector3 wB(0.3, -0.7, 1.2);
    const BodyKinematics A
        = body(Vector3::Zero(), G * rotation(0.3, Vector3::UnitY()),
               Vector3::Zero(), wB + G * Vector3(0, 2, 0));
    const BodyKinematics B = body(Vector3(1, 2, 3), G, Vector3(0.1, 0, 0), wB);
    const connectors::ConnectorResult r = spring.evaluate(A, B);
    // Tolerance: products of O(1) rotations, round-off ~1e-15.
    expectVectorNear(r.A.m_Ko_W, G * Vector3(0, -2.5, 0), 1e-13);
    expectVectorNear(r.A.m_Ko_W + r.B.m_Ko_W, Vector3::Zero(), 1e-15);
    EXPECT_NEAR(r.potentialEnergy, 0.225, 1e-13);
    EXPECT_NEAR(r.dissipatedPower, 2.0, 1e-13);
}

TEST(AxialAngularSpring, PowerOfTurnsAboutTheAxis)
{
    // A turning about the axis at rate s from angle phi: the power into
    // the bodies is -k phi s - c s^2 = -dE/dt - D, and E = k phi^2 / 2,
    // for angles on both sides and up to nearly pi.
    const double k = 3.0, c = 0.25;
    const Vector3 n = Vector3(1, 1, 0).normalized();
    const AxialAngularSpring spring(springParameters(k, c, Vector3(1, 1, 0)));
    for (const double phi : {-2.9, -1.0, -0.01, 0.2, 1.7, 3.0}) {
        const double s = 0.8;
        const BodyKinematics A
            = body(Vector3::Zero(), rotation(phi, n), Vector3::Zero(), s * n);
        const BodyKinematics B = body(Vector3::Zero());
        const connectors::ConnectorResult r = spring.evaluate(A, B);
        // Tolerance: acos loses ~1e-8 rad of the angle near 0 and pi
        // (sqrt of the round-off of u . w): 1e-7.
        EXPECT_NEAR(r.potentialEnergy, 0.5 * k * phi * phi, 1e-7) << phi;
        EXPECT_NEAR(powerIntoBodies(r, A, B), -k * phi * s - c * s * s, 1e-7)
            << phi;
    }
}

TEST(AxialAngularSpringErrors, Messages)
{
    expectThrowWithMessage<ParameterError>(
        [] {
            AxialAngularSpring s(springParameters(-1.0, 0.0, Vector3::UnitZ()));
        },
        "axialAngularSpring: parameter stiffness = -1 N.m/rad is out of "
        "range (allowed: finite and >= 0)");
    expectThrowWithMessage<ParameterError>(
        [] {
            AxialAngularSpring s(springParameters(1.0, 0.0, Vector3::Zero()));
        },
        "axialAngularSpring: parameter B.axis = (0, 0, 0) has no direction "
        "(allowed: a finite vector of length >= 1e-12, normalised by the "
        "law)");
    expectThrowWithMessage<ParameterError>(
        [] {
            AxialAngularSpringParameters p
                = springParameters(1.0, 0.0, Vector3::UnitZ());
            p.R_BA0(1, 2) = std::numeric_limits<double>::infinity();
            AxialAngularSpring s(p);
        },
        "axialAngularSpring: parameter referenceOrientation[2,3] = inf is out "
        "of range (allowed: finite)");
    expectThrowWithMessage<ParameterError>(
        [] {
            AxialAngularSpringParameters p
                = springParameters(1.0, 0.0, Vector3::UnitZ());
            p.R_BA0 *= 2.0; // norm 2 sqrt(3)
            AxialAngularSpring s(p);
        },
        "axialAngularSpring: parameter referenceOrientation is not a rotation "
        "tensor: |referenceOrientation| - sqrt(3) = 1.7320508075688772 "
        "(allowed: within 3.2e-08 of 0, as OpenFOAM reads it)");
    expectNanInputRefused(
        AxialAngularSpring(springParameters(1.0, 0.0, Vector3::UnitZ())),
        &BodyKinematics::w_WK_W, 1,
        "axialAngularSpring: input B.omega[2] = nan is not finite");
}

} // namespace

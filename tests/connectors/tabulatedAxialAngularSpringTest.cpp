// connectors::TabulatedAxialAngularSpring against hand-computed values of
// OpenFOAM's sixDoF tabulatedAxialAngularSpring (radians, degrees, each
// outOfBounds), against axialAngularSpring with the table of a linear
// spring, the energy against the moment, and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "LawTestSupport.hpp"
#include "axialAngularSpring/AxialAngularSpring.hpp"
#include "common/ConnectorError.hpp"
#include "tabulatedAxialAngularSpring/TabulatedAxialAngularSpring.hpp"

namespace {

using namespace lawTest;
using connectors::OutOfBounds;
using connectors::ParameterError;
using connectors::TabulatedAxialAngularSpring;
using connectors::TabulatedAxialAngularSpringParameters;
using connectors::UndefinedStateError;

//- The table (-1, 2) (0, 0) (0.5, -3) [rad, N.m] about y: M = -2 theta
//  below 0, -6 theta above
TabulatedAxialAngularSpringParameters
springParameters(OutOfBounds outOfBounds = OutOfBounds::clamp, double c = 0.0)
{
    TabulatedAxialAngularSpringParameters p;
    p.axis_B = Vector3(0, 2, 0);
    p.angle = {-1.0, 0.0, 0.5};
    p.moment = {2.0, 0.0, -3.0};
    p.outOfBounds = outOfBounds;
    p.damping = c;
    return p;
}

//- The law's result with A turned by theta about y at rate s, B the world
connectors::ConnectorResult turned(const TabulatedAxialAngularSpring& spring,
                                   double theta, double s = 0.0)
{
    return spring.evaluate(body(Vector3(0.5, 0.45, 0.1),
                                rotation(theta, Vector3::UnitY()),
                                Vector3(1, 2, 3), Vector3(0, s, 0)),
                           body(Vector3::Zero()));
}

TEST(TabulatedAxialAngularSpring, AnalyticTurnAboutTheAxis)
{
    // theta = 0.3: M = -6 * 0.3 = -1.8; c = 0.5, rate 2: M_A = -2.8 e_y;
    // E = -integral of -6 s from 0 to 0.3 = 3 * 0.09 = 0.27; D = 0.5 * 4.
    const TabulatedAxialAngularSpring spring(
        springParameters(OutOfBounds::clamp, 0.5));
    const connectors::ConnectorResult r = turned(spring, 0.3, 2.0);
    // Tolerance: acos near 0.3 and products of O(1) values: 1e-14.
    expectVectorNear(r.A.m_Ko_W, Vector3(0, -2.8, 0), 1e-14);
    expectVectorNear(r.B.m_Ko_W, Vector3(0, 2.8, 0), 1e-14);
    EXPECT_EQ(r.A.f_W, Vector3::Zero());
    EXPECT_EQ(r.tension, 0.0);
    // Tolerance: as the moment, the integral adds O(1) terms: 1e-14.
    EXPECT_NEAR(r.potentialEnergy, 0.27, 1e-14);
    EXPECT_NEAR(r.dissipatedPower, 2.0, 1e-14);
}

TEST(TabulatedAxialAngularSpring, TurnedOtherWay)
{
    // theta = -0.3: M = 2 + (0 - 2) 0.7 = 0.6; E = -integral of -2 s from 0
    // to -0.3 = 0.09
    const TabulatedAxialAngularSpring spring(springParameters());
    const connectors::ConnectorResult r = turned(spring, -0.3);
    // Tolerance: as AnalyticTurnAboutTheAxis.
    expectVectorNear(r.A.m_Ko_W, Vector3(0, 0.6, 0), 1e-14);
    EXPECT_NEAR(r.potentialEnergy, 0.09, 1e-14);
}

TEST(TabulatedAxialAngularSpring, Degrees)
{
    // The same table in degrees, (-60, 2) (0, 0) (30, -3): at 0.3 rad,
    // x = 0.3 * 180 / pi deg, M = -0.1 x; E = (pi / 180) 0.05 x^2
    TabulatedAxialAngularSpringParameters p = springParameters();
    p.angle = {-60.0, 0.0, 30.0};
    p.angleInDegrees = true;
    const TabulatedAxialAngularSpring spring(p);
    const double x = 0.3 * 180.0 / pi;
    const connectors::ConnectorResult r = turned(spring, 0.3);
    // Tolerance: the angle's round-off (1e-16 rad) times 180/pi and the
    // slope 0.1: 1e-14.
    expectVectorNear(r.A.m_Ko_W, Vector3(0, -0.1 * x, 0), 1e-14);
    EXPECT_NEAR(r.potentialEnergy, pi / 180.0 * 0.05 * x * x, 1e-14);
}

TEST(TabulatedAxialAngularSpring, ClampAndWarn)
{
    // Beyond 0.5 rad the last moment, -3: E(1.2) = -(-0.75 - 3 * 0.7)
    // = 2.85; below -1 the first, 2: E(-2) = -(-1 - 2) = 3. Warn: the same.
    for (const OutOfBounds b : {OutOfBounds::clamp, OutOfBounds::warn}) {
        const TabulatedAxialAngularSpring spring(springParameters(b));
        const connectors::ConnectorResult above = turned(spring, 1.2);
        const connectors::ConnectorResult below = turned(spring, -2.0);
        // Tolerance: sums of O(1) values: 1e-14.
        expectVectorNear(above.A.m_Ko_W, Vector3(0, -3, 0), 1e-14);
        EXPECT_NEAR(above.potentialEnergy, 2.85, 1e-14);
        expectVectorNear(below.A.m_Ko_W, Vector3(0, 2, 0), 1e-14);
        EXPECT_NEAR(below.potentialEnergy, 3.0, 1e-14);
    }
}

TEST(TabulatedAxialAngularSpring, Repeat)
{
    // Above the table, x = fmod(1.2 + 1, 1.5) - 1 = -0.3: M = 0.6; the
    // integral from -1 over the table is 1 - 0.75 = 0.25, to 1.2 it is
    // 0.25 + 1 - 0.09 = 1.16, to 0 it is 1: E = -0.16. Below, OpenFOAM's
    // repeat gives the first moment, 2 (as clamp).
    const TabulatedAxialAngularSpring spring(
        springParameters(OutOfBounds::repeat));
    const connectors::ConnectorResult above = turned(spring, 1.2);
    // Tolerance: fmod of the angle (round-off 1e-16) and sums of O(1)
    // values: 1e-14.
    expectVectorNear(above.A.m_Ko_W, Vector3(0, 0.6, 0), 1e-14);
    EXPECT_NEAR(above.potentialEnergy, -0.16, 1e-14);
    const connectors::ConnectorResult below = turned(spring, -2.0);
    expectVectorNear(below.A.m_Ko_W, Vector3(0, 2, 0), 1e-14);
    EXPECT_NEAR(below.potentialEnergy, 3.0, 1e-14);
}

TEST(TabulatedAxialAngularSpring, ErrorOutsideTheTable)
{
    const TabulatedAxialAngularSpring spring(
        springParameters(OutOfBounds::error));
    // Inside: as clamp
    expectVectorNear(turned(spring, 0.3).A.m_Ko_W, Vector3(0, -1.8, 0), 1e-14);
    expectThrowWithMessage<UndefinedStateError>(
        [&] { turned(spring, 1.25); },
        "tabulatedAxialAngularSpring: angle 1.25 rad outside the table's "
        "[-1, 0.5) with outOfBounds error (0)");
}

TEST(TabulatedAxialAngularSpring, LinearTableIsAxialAngularSpring)
{
    // The table (-pi, k pi) (pi, -k pi): OpenFOAM's linearAxialAngularSpring
    // with stiffness k; random orientations of A and B about random axes
    // (the angle never exactly 0, where linear's damping vanishes).
    const double k = 3.0, c = 0.25;
    const Vector3 axis(0.3, -1, 0.2);
    connectors::AxialAngularSpringParameters lp;
    lp.axis_B = axis;
    lp.stiffness = k;
    lp.damping = c;
    const connectors::AxialAngularSpring linear(lp);
    TabulatedAxialAngularSpringParameters tp;
    tp.axis_B = axis;
    tp.angle = {-pi, pi};
    tp.moment = {k * pi, -k * pi};
    tp.damping = c;
    const TabulatedAxialAngularSpring tabulated(tp);
    std::mt19937 rng(11);
    for (int i = 0; i < 200; ++i) {
        const BodyKinematics A = randomBody(rng), B = randomBody(rng);
        const connectors::ConnectorResult l = linear.evaluate(A, B);
        const connectors::ConnectorResult t = tabulated.evaluate(A, B);
        // Tolerance: the same angle, the moment k theta through the table's
        // slope (2 k pi) / (2 pi) and the energy as a sum of trapezoids
        // (terms of k pi^2 ~ 30): round-off, 1e-13.
        expectVectorNear(t.A.m_Ko_W, l.A.m_Ko_W, 1e-13);
        expectVectorNear(t.B.m_Ko_W, l.B.m_Ko_W, 1e-13);
        EXPECT_NEAR(t.potentialEnergy, l.potentialEnergy, 1e-13) << i;
        EXPECT_NEAR(t.dissipatedPower, l.dissipatedPower, 1e-13) << i;
        EXPECT_EQ(t.length, l.length);
    }
}

TEST(TabulatedAxialAngularSpring, RelativeToBody)
{
    // Everything turned by G and B spinning: the moment turns with G, the
    // energy and the dissipation are the same.
    const TabulatedAxialAngularSpring spring(
        springParameters(OutOfBounds::clamp, 0.5));
    const Matrix3 G = rotation(1.1, Vector3(1, -2, 0.5));
    const Vector3 wB(0.3, -0.7, 1.2);
    const BodyKinematics A
        = body(Vector3::Zero(), G * rotation(0.3, Vector3::UnitY()),
               Vector3::Zero(), wB + G * Vector3(0, 2, 0));
    const BodyKinematics B = body(Vector3(1, 2, 3), G, Vector3(0.1, 0, 0), wB);
    const connectors::ConnectorResult r = spring.evaluate(A, B);
    // Tolerance: products of O(1) rotations, round-off ~1e-15.
    expectVectorNear(r.A.m_Ko_W, G * Vector3(0, -2.8, 0), 1e-13);
    expectVectorNear(r.A.m_Ko_W + r.B.m_Ko_W, Vector3::Zero(), 1e-15);
    EXPECT_NEAR(r.potentialEnergy, 0.27, 1e-13);
    EXPECT_NEAR(r.dissipatedPower, 2.0, 1e-13);
}

TEST(TabulatedAxialAngularSpring, EnergyIsTheIntegralOfTheMoment)
{
    // For turns about the axis at rate s from angle phi the power into the
    // bodies is M s - c s^2 = -dE/dt - D: dE/dphi = -M, by central
    // differences of the piecewise quadratic E within one piece (exact up
    // to round-off); each outOfBounds but error.
    const double c = 0.25, s = 0.8, h = 1e-4;
    for (const OutOfBounds b :
         {OutOfBounds::warn, OutOfBounds::clamp, OutOfBounds::repeat}) {
        const TabulatedAxialAngularSpring spring(springParameters(b, c));
        for (const double phi : {-2.9, -1.5, -0.4, 0.2, 0.45, 0.9, 2.95}) {
            const BodyKinematics A
                = body(Vector3::Zero(), rotation(phi, Vector3::UnitY()),
                       Vector3::Zero(), Vector3(0, s, 0));
            const BodyKinematics B = body(Vector3::Zero());
            const connectors::ConnectorResult r = spring.evaluate(A, B);
            const double M = r.A.m_Ko_W.y() + c * s;
            const double dE = (turned(spring, phi + h).potentialEnergy
                               - turned(spring, phi - h).potentialEnergy)
                / (2 * h);
            // Tolerance: energies of O(1) to round-off 1e-15 over 2h, and
            // acos near 3 rad, close to pi, loses ~1e-8 rad: 1e-7.
            EXPECT_NEAR(dE, -M, 1e-7) << phi;
            EXPECT_NEAR(powerIntoBodies(r, A, B), M * s - c * s * s, 1e-14)
                << phi;
            EXPECT_NEAR(r.dissipatedPower, c * s * s, 1e-15);
        }
    }
}

TEST(TabulatedAxialAngularSpringErrors, Messages)
{
    const auto refused = [](auto change, const std::string& message) {
        expectThrowWithMessage<ParameterError>(
            [&] {
                TabulatedAxialAngularSpringParameters p = springParameters();
                change(p);
                TabulatedAxialAngularSpring s(p);
            },
            message);
    };
    refused(
        [](auto& p) {
            p.angle = {0.2, 0.1, 0.5};
        },
        "tabulatedAxialAngularSpring: parameter table.angle[2] = 0.1 rad "
        "is out of range (allowed: > table.angle[1] = 0.2: the angles "
        "strictly increasing)");
    refused(
        [](auto& p) {
            p.angle = {0.0, 10.0, 10.0};
            p.angleInDegrees = true;
        },
        "tabulatedAxialAngularSpring: parameter table.angle[3] = 10 deg is "
        "out of range (allowed: > table.angle[2] = 10: the angles strictly "
        "increasing)");
    refused(
        [](auto& p) {
            p.angle = {0.0};
            p.moment = {1.0};
        },
        "tabulatedAxialAngularSpring: parameter table.points = 1 is out of "
        "range (allowed: an integer >= 2, one moment per angle)");
    refused(
        [](auto& p) { p.moment[1] = std::numeric_limits<double>::quiet_NaN(); },
        "tabulatedAxialAngularSpring: parameter table.moment[2] = nan N.m is "
        "out of range (allowed: finite)");
    refused([](auto& p) { p.damping = -1.0; },
            "tabulatedAxialAngularSpring: parameter damping = -1 N.m.s/rad is "
            "out of range (allowed: finite and >= 0)");
    refused([](auto& p) { p.axis_B = Vector3::Zero(); },
            "tabulatedAxialAngularSpring: parameter B.axis = (0, 0, 0) has no "
            "direction (allowed: a finite vector of length >= 1e-12, "
            "normalised by the law)");
    refused([](auto& p) { p.R_BA0 *= 2.0; }, // norm 2 sqrt(3)
            "tabulatedAxialAngularSpring: parameter referenceOrientation is "
            "not a rotation tensor: |referenceOrientation| - sqrt(3) = "
            "1.7320508075688772 (allowed: within 3.2e-08 of 0, as OpenFOAM "
            "reads it)");
    expectNanInputRefused(
        TabulatedAxialAngularSpring(springParameters()),
        &BodyKinematics::w_WK_W, 1,
        "tabulatedAxialAngularSpring: input B.omega[2] = nan is not finite");
}

} // namespace

// connectors::Hinge against analytic values and balance laws: zero load on
// the constraint at any angle, gap and misalignment responses, PTO torque
// and power, equal and opposite loads, energy and power balance.
#include <gtest/gtest.h>

#include <cmath>

#include "HingeTestSupport.hpp"

namespace {

using namespace lawTest;

HingeParameters plainHinge(double k, double c, double kr, double cr)
{
    HingeParameters p;
    p.stiffness = k;
    p.damping = c;
    p.rotationalStiffness = kr;
    p.rotationalDamping = cr;
    return p;
}

TEST(Hinge, NoLoadWhenTheConstraintHoldsAtAnyAngle)
{
    HingeParameters p = genericHinge();
    p.ptoStiffness = 0.0;
    p.ptoDamping = 0.0;
    const Hinge hinge(p);
    std::mt19937 rng(7);
    for (const double angle : {0.0, 0.5, -1.2, 2.9, -3.1}) {
        const BodyKinematics A = randomBody(rng);
        const BodyKinematics B = hingedBody(hinge, A, angle, 1.7);
        const HingeResult h = hinge.evaluate(A, B, 0.0);
        // Tolerance: B is built from A with O(1) coordinates, so Q - P and
        // a_B - a_A are round-off, ~1e-15; times k = 800 N/m, k_r = 300
        // N.m/rad and lever arms < 1 m: loads ~1e-12. 1e-10 leaves 100x.
        expectVectorNear(h.loads.A.f_W, Vector3::Zero(), 1e-10);
        expectVectorNear(h.loads.A.m_Ko_W, Vector3::Zero(), 1e-10);
        expectVectorNear(h.loads.B.m_Ko_W, Vector3::Zero(), 1e-10);
        EXPECT_NEAR(h.angle, angle, 1e-12) << angle;
        EXPECT_NEAR(h.angleRate, 1.7, 1e-12);
        EXPECT_NEAR(h.gap, 0.0, 1e-14);
        // acos-like loss near zero: atan2(|u|, c) of a ~1e-16 |u|
        EXPECT_NEAR(h.misalignment, 0.0, 1e-14);
        EXPECT_NEAR(h.loads.dissipatedPower, 0.0, 1e-20);
    }
}

TEST(Hinge, GapGivesASpringDamperForce)
{
    // Q 0.01 m from P along x, closing at 0.2 m/s: f_A = k d + c v_PQ =
    // 1000 (0.01,0,0) + 20 (-0.2,0,0) = (6, 0, 0) N, pulling P towards Q.
    const Hinge hinge(plainHinge(1000.0, 20.0, 50.0, 1.0));
    const BodyKinematics A = body(Vector3::Zero());
    const BodyKinematics B
        = body(Vector3(0.01, 0, 0), Matrix3::Identity(), Vector3(-0.2, 0, 0));
    const HingeResult h = hinge.evaluate(A, B, 0.0);
    // 0.01 is not exact in binary; k 0.01 = 10 to ~2e-15.
    expectVectorNear(h.loads.A.f_W, Vector3(6, 0, 0), 1e-13);
    expectVectorNear(h.loads.B.f_W, Vector3(-6, 0, 0), 1e-13);
    expectVectorNear(h.loads.A.m_Ko_W, Vector3::Zero(), 0.0);
    EXPECT_NEAR(h.loads.tension, 6.0, 1e-13);
    EXPECT_NEAR(h.gap, 0.01, 1e-17);
    EXPECT_NEAR(h.loads.lengthRate, -0.2, 1e-16);
    EXPECT_NEAR(h.loads.potentialEnergy, 0.5 * 1000.0 * 1e-4, 1e-16);
    EXPECT_NEAR(h.loads.dissipatedPower, 20.0 * 0.04, 1e-15);
}

TEST(Hinge, MisalignmentGivesAnAligningMoment)
{
    // B turned 0.2 rad about x: a_B = (0, -sin 0.2, cos 0.2), theta = 0.2,
    // n = unit(a_B x a_A) = (-1, 0, 0): M_B = k_r theta n = (-10, 0, 0).
    const Hinge hinge(plainHinge(0.0, 0.0, 50.0, 0.0));
    const HingeResult h = hinge.evaluate(
        body(Vector3::Zero()),
        body(Vector3::Zero(), rotation(0.2, Vector3::UnitX())), 0.0);
    // Tolerance: rotation matrix entries and atan2 to a few ulps of 1.
    EXPECT_NEAR(h.misalignment, 0.2, 1e-15);
    expectVectorNear(h.loads.B.m_Ko_W, Vector3(-10, 0, 0), 1e-13);
    expectVectorNear(h.loads.A.m_Ko_W, Vector3(10, 0, 0), 1e-13);
    expectVectorNear(h.loads.A.f_W, Vector3::Zero(), 0.0);
    EXPECT_NEAR(h.loads.potentialEnergy, 0.5 * 50.0 * 0.04, 1e-14);
    // Static misalignment = moment / rotationalStiffness
    EXPECT_NEAR(h.misalignment, h.loads.B.m_Ko_W.norm() / 50.0, 1e-15);
}

TEST(Hinge, RotationalDampingActsAcrossTheAxisOnly)
{
    // w_B - w_A = (1, 0, 3): the x part is damped (c_r = 2), the z part
    // (about the axis) is free without a PTO.
    const Hinge hinge(plainHinge(0.0, 0.0, 0.0, 2.0));
    const BodyKinematics A = body(Vector3::Zero());
    const BodyKinematics B = body(Vector3::Zero(), Matrix3::Identity(),
                                  Vector3::Zero(), Vector3(1, 0, 3));
    const HingeResult h = hinge.evaluate(A, B, 0.0);
    EXPECT_EQ(h.loads.B.m_Ko_W, Vector3(-2, 0, 0));
    EXPECT_EQ(h.loads.A.m_Ko_W, Vector3(2, 0, 0));
    EXPECT_EQ(h.angleRate, 3.0);
    EXPECT_EQ(h.loads.dissipatedPower, 2.0);
}

TEST(Hinge, PtoTorqueAndPowerSigns)
{
    // B at +0.3 rad about z (the axis), turning at +2 rad/s. k_p = 10,
    // phi0 = 0.1, c_p = 4: tau = 10 * 0.2 + 4 * 2 = 10 N.m, resisting: the
    // moment on B is -tau z, on A +tau z; absorbed power tau * 2 = 20 W.
    HingeParameters p = plainHinge(0.0, 0.0, 0.0, 0.0);
    p.ptoStiffness = 10.0;
    p.ptoDamping = 4.0;
    p.ptoRestAngle = 0.1;
    const Hinge hinge(p);
    const BodyKinematics A = body(Vector3::Zero());
    const BodyKinematics B
        = body(Vector3::Zero(), rotation(0.3, Vector3::UnitZ()),
               Vector3::Zero(), Vector3(0, 0, 2));
    const HingeResult h = hinge.evaluate(A, B, 0.0);
    // angle from atan2 of cos/sin 0.3: a few ulps
    EXPECT_NEAR(h.angle, 0.3, 1e-15);
    EXPECT_NEAR(h.ptoTorque, 10.0, 1e-14);
    EXPECT_NEAR(h.ptoPower, 20.0, 1e-13);
    expectVectorNear(h.loads.B.m_Ko_W, Vector3(0, 0, -10), 1e-14);
    expectVectorNear(h.loads.A.m_Ko_W, Vector3(0, 0, 10), 1e-14);
    EXPECT_NEAR(h.loads.potentialEnergy, 0.5 * 10.0 * 0.04, 1e-15);
    EXPECT_NEAR(h.loads.dissipatedPower, 4.0 * 4.0, 1e-15);
    // Power into the bodies from the PTO is minus the absorbed power.
    EXPECT_NEAR(powerIntoBodies(h.loads, A, B), -h.ptoPower, 1e-13);
    // Turning the other way at the same angle: the damper still absorbs,
    // the spring returns energy: tau = 2 - 8 = -6, ptoPower = 12 W > 0.
    const BodyKinematics Bback
        = body(Vector3::Zero(), B.R_WK, Vector3::Zero(), Vector3(0, 0, -2));
    EXPECT_NEAR(hinge.evaluate(A, Bback, 0.0).ptoPower, 12.0, 1e-13);
}

TEST(Hinge, EqualAndOppositeLoadsAndZeroTotalMoment)
{
    const Hinge hinge(genericHinge());
    std::mt19937 rng(2024);
    for (int i = 0; i < 50; ++i) {
        const BodyKinematics A = randomBody(rng);
        const BodyKinematics B = randomBody(rng);
        const HingeResult h = hinge.evaluate(A, B, 0.0);
        expectAllFinite(h.loads);
        EXPECT_EQ(h.loads.A.f_W, -h.loads.B.f_W);
        // Tolerance: forces up to ~1e4 N at lever arms of ~5 m; the sum of
        // four terms cancels to round-off ~1e4 * 5 * 1e-16 * 10 = 5e-11.
        expectVectorNear(totalMomentAboutOrigin(h.loads, A, B), Vector3::Zero(),
                         1e-9);
        EXPECT_GE(h.loads.dissipatedPower, 0.0);
        EXPECT_GE(h.loads.potentialEnergy, 0.0);
        EXPECT_GE(h.misalignment, 0.0);
        EXPECT_LE(h.misalignment, EIGEN_PI);
    }
}

TEST(Hinge, DampersOnlyDissipate)
{
    // Without springs the power into the bodies is exactly minus the
    // dissipated power, which is never negative.
    HingeParameters p = genericHinge();
    p.stiffness = p.rotationalStiffness = p.ptoStiffness = 0.0;
    const Hinge hinge(p);
    std::mt19937 rng(99);
    for (int i = 0; i < 50; ++i) {
        const BodyKinematics A = randomBody(rng);
        const BodyKinematics B = randomBody(rng);
        const HingeResult h = hinge.evaluate(A, B, 0.0);
        EXPECT_GE(h.loads.dissipatedPower, 0.0);
        // Power terms ~1e2 W; round-off ~1e-13 W.
        EXPECT_NEAR(powerIntoBodies(h.loads, A, B), -h.loads.dissipatedPower,
                    1e-10 * (1.0 + h.loads.dissipatedPower));
    }
}

//- dV/dt along the bodies' motion by a central difference
double energyRate(const Hinge& hinge, const BodyKinematics& A,
                  const BodyKinematics& B, double angle)
{
    const double dt = 1e-6;
    const double plus = hinge.evaluate(advanced(A, dt), advanced(B, dt), angle)
                            .loads.potentialEnergy;
    const double minus
        = hinge.evaluate(advanced(A, -dt), advanced(B, -dt), angle)
              .loads.potentialEnergy;
    return (plus - minus) / (2 * dt);
}

TEST(Hinge, SpringsAreConservative)
{
    // Power into the bodies = -dV/dt - dissipatedPower. Without a PTO this
    // holds for any motion; with the PTO spring the angle rate w . a_A is
    // the angle's derivative only while the axes are aligned, so that case
    // uses a hinged B (here with a gap added to keep the penalty loaded).
    std::mt19937 rng(5);
    HingeParameters noPto = genericHinge();
    noPto.ptoStiffness = 0.0;
    const Hinge free(noPto);
    const Hinge withPto(genericHinge());
    for (int i = 0; i < 20; ++i) {
        const BodyKinematics A = randomBody(rng);
        const BodyKinematics B = randomBody(rng);
        const HingeResult h = free.evaluate(A, B, 0.0);
        // Central difference error ~ dt^2 V''' ~ 1e-12 * 1e4; round-off
        // ~ 1e-16 V / dt ~ 1e-7 W on V ~ 1e3 J: 1e-5 relative to the power
        // scale (~1e3 W) is the bound.
        const double scale = 1.0 + h.loads.dissipatedPower
            + std::abs(energyRate(free, A, B, 0.0));
        EXPECT_NEAR(powerIntoBodies(h.loads, A, B),
                    -energyRate(free, A, B, 0.0) - h.loads.dissipatedPower,
                    1e-6 * scale)
            << i;

        BodyKinematics Bh = hingedBody(withPto, A, 1.0 + 0.2 * i, -0.8);
        Bh.p_WKo_W += Vector3(0.01, -0.02, 0.005);
        const HingeResult hp = withPto.evaluate(A, Bh, 0.0);
        const double rate = energyRate(withPto, A, Bh, hp.angle);
        EXPECT_NEAR(powerIntoBodies(hp.loads, A, Bh),
                    -rate - hp.loads.dissipatedPower,
                    1e-6 * (1.0 + hp.loads.dissipatedPower + std::abs(rate)))
            << i;
    }
}

} // namespace

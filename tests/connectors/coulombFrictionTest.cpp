// connectors::CoulombFriction against analytic values: force direction and
// magnitude, the guide projection, symmetry of A and B, balance laws,
// refusals of bad parameters, and the energy dissipated per cycle of a
// harmonic sliding against Coulomb's 4 F_c X and the law's closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "LawTestSupport.hpp"
#include "common/ConnectorError.hpp"
#include "coulombFriction/CoulombFriction.hpp"

namespace {

using namespace lawTest;
using connectors::CoulombFriction;
using connectors::CoulombFrictionParameters;
using connectors::CoulombFrictionResult;
using connectors::ParameterError;

CoulombFrictionParameters
frictionParameters(double Fc, double vs, const Vector3& axis = Vector3::Zero(),
                   const Vector3& pA = Vector3::Zero(),
                   const Vector3& pB = Vector3::Zero())
{
    return {pA, pB, axis, Fc, vs}; // in the order of the members
}

TEST(CoulombFriction, AnalyticSlidingAlongAGuide)
{
    // World B, guide x (given as (2,0,0): normalised). A slides with
    // u = (0.03, 0.5, -0.2): only u_x = 0.03 counts; v_s = 0.04 gives
    // sqrt(0.03^2 + 0.04^2) = 0.05, F = -2 * 0.03/0.05 = -1.2 N along x,
    // D = 2 * 0.03^2/0.05 = 0.036 W. P = A's reference point: no moment on
    // A; on B (the world, at the origin) (1,2,3) x (1.2,0,0) = (0,3.6,-2.4).
    const CoulombFriction law(frictionParameters(2.0, 0.04, Vector3(2, 0, 0)));
    const CoulombFrictionResult r = law.evaluateSliding(
        body(Vector3(1, 2, 3), rotation(0.7, Vector3(1, 1, 0)),
             Vector3(0.03, 0.5, -0.2), Vector3(0.3, -0.1, 0.2)),
        body(Vector3::Zero()));
    // Tolerance: a handful of operations on O(1) values: ~1e-16.
    const double tol = 1e-14;
    expectVectorNear(r.loads.A.f_W, Vector3(-1.2, 0, 0), tol);
    expectVectorNear(r.loads.B.f_W, Vector3(1.2, 0, 0), tol);
    expectVectorNear(r.loads.A.m_Ko_W, Vector3::Zero(), tol);
    expectVectorNear(r.loads.B.m_Ko_W, Vector3(0, 3.6, -2.4), tol);
    EXPECT_NEAR(r.loads.dissipatedPower, 0.036, tol);
    EXPECT_EQ(r.loads.potentialEnergy, 0.0);
    EXPECT_NEAR(r.slidingVelocity, 0.03, tol);
    EXPECT_NEAR(r.friction, -1.2, tol);
}

TEST(CoulombFriction, AnalyticGuideOnATurningBody)
{
    // B at the origin, turned 90 deg about z and spinning at 1 rad/s about
    // z; its guide x is global y. A's point P at (2,0,0) (A.p = 0) moves
    // at (0, 2.03, 0); B's material point there moves at (0,0,1) x (2,0,0)
    // = (0,2,0): u = (0, 0.03, 0). F_c = 2, v_s = 0.04: f_A = (0,-1.2,0),
    // m_B = (2,0,0) x (0,1.2,0) = (0,0,2.4) (the reaction at P, not at B.p).
    // Q = B's origin: length 2, e_PQ = (-1,0,0), tension f_A . e = 0,
    // lengthRate = e . (v_Q - v_P) = 0.
    const CoulombFriction law(frictionParameters(2.0, 0.04, Vector3(1, 0, 0)));
    const CoulombFrictionResult r = law.evaluateSliding(
        body(Vector3(2, 0, 0), Matrix3::Identity(), Vector3(0, 2.03, 0)),
        body(Vector3::Zero(), rotation(EIGEN_PI / 2, Vector3::UnitZ()),
             Vector3::Zero(), Vector3(0, 0, 1)));
    // Tolerance: u = 2.03 - 2 cancels: 2.03 is stored to ~2e-16 m/s, a
    // relative 7e-15 of u = 0.03, which the force and moment inherit
    // (measured 1e-14 on m_B): 1e-13.
    const double tol = 1e-13;
    expectVectorNear(r.loads.A.f_W, Vector3(0, -1.2, 0), tol);
    expectVectorNear(r.loads.A.m_Ko_W, Vector3::Zero(), tol);
    expectVectorNear(r.loads.B.m_Ko_W, Vector3(0, 0, 2.4), tol);
    EXPECT_NEAR(r.slidingVelocity, 0.03, tol);
    EXPECT_NEAR(r.loads.dissipatedPower, 0.036, tol);
    EXPECT_NEAR(r.loads.length, 2.0, tol);
    EXPECT_NEAR(r.loads.lengthRate, 0.0, tol);
    EXPECT_NEAR(r.loads.tension, 0.0, tol);
}

TEST(CoulombFriction, EveryDirectionOpposesTheSlidingAtTheRegularisedMagnitude)
{
    // Without an axis the force is antiparallel to u with magnitude
    // F_c |u| / sqrt(|u|^2 + v_s^2): below F_c, ~F_c |u|/v_s at |u| << v_s,
    // ~F_c (1 - v_s^2/(2|u|^2)) at |u| >> v_s.
    const double Fc = 0.4, vs = 1e-3;
    const CoulombFriction law(frictionParameters(Fc, vs));
    const Vector3 direction = Vector3(1, -2, 2) / 3.0;
    for (const double speed : {1e-7, 1e-4, 1e-3, 0.05, 0.3, 10.0}) {
        const CoulombFrictionResult r
            = law.evaluateSliding(body(Vector3(0.1, 0.2, 0.3),
                                       Matrix3::Identity(), speed * direction),
                                  body(Vector3(-1, 0, 0)));
        const Vector3 f = r.loads.A.f_W;
        const double magnitude = Fc * speed / std::hypot(speed, vs);
        // Tolerance: round-off of O(1e-16) on forces below 0.4 N.
        EXPECT_NEAR(f.norm(), magnitude, 1e-15) << speed;
        EXPECT_NEAR(f.normalized().dot(direction), -1.0, 1e-14) << speed;
        EXPECT_LT(f.norm(), Fc);
        EXPECT_NEAR(r.friction, magnitude, 1e-15);
        EXPECT_NEAR(r.slidingVelocity, speed, 1e-15 * speed);
        if (speed <= 1e-4 * vs) {
            // Linear damper F_c/v_s: relative error (u/v_s)^2/2 = 5e-9
            EXPECT_NEAR(f.norm(), Fc * speed / vs, 1e-8 * Fc * speed / vs);
        }
        if (speed >= 100 * vs) {
            // 1 - v_s^2/(2u^2): next term 3/8 (v_s/u)^4 <= 4e-9
            EXPECT_NEAR(f.norm(), Fc * (1 - vs * vs / (2 * speed * speed)),
                        4e-9 * Fc);
        }
    }
}

TEST(CoulombFriction, GuideKeepsOnlyTheAxialSliding)
{
    // Axis (1,1,0) in B's frame, B turned: only u . a counts. The force of
    // a velocity equals that of its axial part alone; motion across the
    // guide gives none.
    const Matrix3 R_B = rotation(0.9, Vector3(0.3, -1, 2));
    const Vector3 a_W = R_B * Vector3(1, 1, 0).normalized();
    const CoulombFriction law(frictionParameters(0.5, 0.01, Vector3(1, 1, 0)));
    const Vector3 across = a_W.cross(Vector3(0.2, 0.7, -0.4));
    const Vector3 along = 0.02 * a_W;
    const auto force = [&](const Vector3& u) {
        return law.evaluate(body(Vector3(0.5, 0, 0), Matrix3::Identity(), u),
                            body(Vector3(0, 1, 0), R_B));
    };
    const ConnectorResult mixed = force(along + across);
    const ConnectorResult axial = force(along);
    // Tolerance: the projections differ in the last bits only.
    expectVectorNear(mixed.A.f_W, axial.A.f_W, 1e-15);
    EXPECT_NEAR(mixed.dissipatedPower, axial.dissipatedPower, 1e-16);
    // |f| = 0.5 * 0.02/sqrt(0.02^2 + 0.01^2) = 0.5 * 2/sqrt(5), along -a
    expectVectorNear(axial.A.f_W, -0.5 * 2 / std::sqrt(5.0) * a_W, 1e-15);
    const ConnectorResult crossing = force(across);
    // Tolerance: a . across ~ 1e-17 (round-off of the cross product).
    expectVectorNear(crossing.A.f_W, Vector3::Zero(), 1e-15);
    EXPECT_NEAR(crossing.dissipatedPower, 0.0, 1e-16);
}

TEST(CoulombFriction, SwappingAAndBReversesTheLoads)
{
    // P and Q at one global point (the contact), both bodies moving and
    // turning: evaluating with A and B swapped gives each body the load
    // the other had. With a guide, both frames are the same so that the
    // axis is the same in the global frame.
    std::mt19937 rng(7);
    for (const bool guided : {false, true}) {
        for (int i = 0; i < 100; ++i) {
            BodyKinematics A = randomBody(rng);
            BodyKinematics B = randomBody(rng);
            if (guided) {
                B.R_WK = A.R_WK;
            }
            const Vector3 contact(0.3, -0.2, 0.5);
            const Vector3 pA = A.R_WK.transpose() * (contact - A.p_WKo_W);
            const Vector3 pB = B.R_WK.transpose() * (contact - B.p_WKo_W);
            const Vector3 axis = guided ? Vector3(0, 1, 2) : Vector3::Zero();
            const ConnectorResult r
                = CoulombFriction(frictionParameters(0.3, 0.05, axis, pA, pB))
                      .evaluate(A, B);
            const ConnectorResult s
                = CoulombFriction(frictionParameters(0.3, 0.05, axis, pB, pA))
                      .evaluate(B, A);
            // Tolerance: forces below 0.3 N, arms below ~4 m; the two
            // evaluations round differently: 1e-14.
            expectVectorNear(s.A.f_W, r.B.f_W, 1e-14);
            expectVectorNear(s.B.f_W, r.A.f_W, 1e-14);
            expectVectorNear(s.A.m_Ko_W, r.B.m_Ko_W, 1e-14);
            expectVectorNear(s.B.m_Ko_W, r.A.m_Ko_W, 1e-14);
            EXPECT_NEAR(s.dissipatedPower, r.dissipatedPower, 1e-14);
        }
    }
}

TEST(CoulombFriction, DissipatesAndBalances)
{
    // Random geometries with P and Q apart, guided and not: D >= 0, the
    // power into the bodies is exactly -D, the forces are equal and
    // opposite and the total moment about the origin is zero (both act at
    // P), whatever B.p.
    std::mt19937 rng(2026);
    for (const Vector3& axis : {Vector3(0, 0, 0), Vector3(0.2, -1, 0.4)}) {
        const CoulombFriction law(frictionParameters(
            0.45, 0.02, axis, Vector3(0.4, 0.1, -0.2), Vector3(0, 0.3, 0.3)));
        for (int i = 0; i < 500; ++i) {
            const BodyKinematics A = randomBody(rng);
            const BodyKinematics B = randomBody(rng);
            const ConnectorResult r = law.evaluate(A, B);
            expectAllFinite(r);
            EXPECT_GE(r.dissipatedPower, 0.0);
            EXPECT_LE(r.A.f_W.norm(), 0.45);
            // Tolerance: powers up to ~10 W, round-off ~1e-16 relative.
            EXPECT_NEAR(powerIntoBodies(r, A, B), -r.dissipatedPower, 1e-13);
            EXPECT_EQ(r.A.f_W + r.B.f_W, Vector3::Zero());
            // Tolerance: arms of O(4) m times forces below 0.45 N.
            expectVectorNear(totalMomentAboutOrigin(r, A, B), Vector3::Zero(),
                             1e-14);
        }
    }
}

TEST(CoulombFriction, NoLoadAtRestOrWithoutFriction)
{
    const BodyKinematics A
        = body(Vector3(1, 2, 3), rotation(0.4, Vector3(1, 0, 1)));
    const BodyKinematics B = body(Vector3(0, 1, 0));
    const ConnectorResult rest
        = CoulombFriction(frictionParameters(0.3, 1e-3, Vector3(1, 0, 0)))
              .evaluate(A, B);
    EXPECT_EQ(rest.A.f_W, Vector3::Zero());
    EXPECT_EQ(rest.dissipatedPower, 0.0);
    const ConnectorResult frictionless
        = CoulombFriction(frictionParameters(0.0, 1e-3))
              .evaluate(
                  body(Vector3::Zero(), Matrix3::Identity(), Vector3(3, 0, 0)),
                  B);
    EXPECT_EQ(frictionless.A.f_W, Vector3::Zero());
    EXPECT_EQ(frictionless.dissipatedPower, 0.0);
}

TEST(CoulombFriction, ExtremeVelocitiesGiveFiniteLoads)
{
    // hypot keeps |u|^2 from overflowing: at 1e200 m/s the force is F_c.
    const CoulombFriction law(frictionParameters(0.3, 1e-3));
    const ConnectorResult r = law.evaluate(
        body(Vector3::Zero(), Matrix3::Identity(), Vector3(1e200, 1e200, 0)),
        body(Vector3(1, 0, 0)));
    expectAllFinite(r);
    EXPECT_NEAR(r.A.f_W.norm(), 0.3, 1e-15);
}

// Energy dissipated over one period of x = X sin(w t) of A along the
// guide of the world B, by the periodic trapezoidal rule over N samples of
// the law's dissipatedPower and of the work -f . v of its force.
struct CycleEnergy {
    double fromPower, fromWork;
};

CycleEnergy cycleEnergy(const CoulombFriction& law, double X, double w, int N)
{
    const double period = 2 * EIGEN_PI / w, h = period / N;
    CycleEnergy e {0, 0};
    for (int i = 0; i < N; ++i) {
        const double t = i * h;
        const Vector3 v(X * w * std::cos(w * t), 0, 0);
        const ConnectorResult r = law.evaluate(
            body(Vector3(X * std::sin(w * t), 0, 0), Matrix3::Identity(), v),
            body(Vector3::Zero()));
        e.fromPower += h * r.dissipatedPower;
        e.fromWork -= h * r.A.f_W.dot(v);
    }
    return e;
}

TEST(CoulombFrictionEnergy, HarmonicSlidingDissipatesCoulombsFourFcX)
{
    // Pure Coulomb friction dissipates 4 F_c X per cycle (F_c over the
    // path 4X). The regularised law's exact value, with e = v_s/(X w) and
    // k = 1/sqrt(1 + e^2), is 4 F_c X [sqrt(1+e^2) E(k) - e^2/sqrt(1+e^2)
    // K(k)] (complete elliptic integrals; connectors/coulombFriction/
    // README.md), 4 F_c X (1 - (e^2/2)(ln(4/e) - 1/2) + O(e^4 ln e)).
    const double Fc = 0.35, X = 0.05, w = 2 * EIGEN_PI * 0.8; // rig-like
    const double coulomb = 4 * Fc * X;
    double previousDeficit = 1.0;
    for (const double e : {1e-1, 1e-2, 1e-3}) {
        const CoulombFriction law(
            frictionParameters(Fc, e * X * w, Vector3(1, 0, 0)));
        const double k = 1 / std::sqrt(1 + e * e);
        const double exact = coulomb
            * (std::sqrt(1 + e * e) * std::comp_ellint_2(k)
               - e * e / std::sqrt(1 + e * e) * std::comp_ellint_1(k));
        // N = 2^16: the integrand is periodic and analytic within e of the
        // real axis (its branch points at cos(wt) = +-i e), so the
        // trapezoidal error is ~exp(-N e) < 1e-28; what is left is the
        // round-off of 65536 sums, ~1e-13 relative.
        const CycleEnergy got = cycleEnergy(law, X, w, 1 << 16);
        EXPECT_NEAR(got.fromPower, exact, 1e-12 * coulomb) << "e = " << e;
        EXPECT_NEAR(got.fromWork, exact, 1e-12 * coulomb) << "e = " << e;
        // Against Coulomb: the deficit is the asymptotic one; its next
        // term is O(e^2) relative to it: 0.31 % measured at e = 0.1, so
        // 1 % of the deficit at e = 0.1 and 1e-4 of it below.
        const double deficit = (coulomb - got.fromPower) / coulomb;
        const double asymptotic = e * e / 2 * (std::log(4 / e) - 0.5);
        EXPECT_NEAR(deficit, asymptotic, (e > 0.05 ? 1e-2 : 1e-4) * asymptotic)
            << "e = " << e;
        // It converges to 4 F_c X from below as v_s -> 0
        EXPECT_GT(deficit, 0.0);
        EXPECT_LT(deficit, previousDeficit / 50) << "e = " << e;
        previousDeficit = deficit;
    }
    // At e = 1e-3 the regularised law is Coulomb's within 4e-6 (deficit
    // 3.9e-6, the formula above).
    const CoulombFriction fine(
        frictionParameters(Fc, 1e-3 * X * w, Vector3(1, 0, 0)));
    EXPECT_NEAR(cycleEnergy(fine, X, w, 1 << 16).fromPower, coulomb,
                4e-6 * coulomb);
}

TEST(CoulombFrictionErrors, Messages)
{
    expectThrowWithMessage<ParameterError>(
        [] { CoulombFriction f(frictionParameters(-0.2, 1e-3)); },
        "coulombFriction: parameter frictionForce = -0.2 N is out of range "
        "(allowed: finite and >= 0)");
    expectThrowWithMessage<ParameterError>(
        [] {
            CoulombFriction f(frictionParameters(
                std::numeric_limits<double>::quiet_NaN(), 1e-3));
        },
        "coulombFriction: parameter frictionForce = nan N is out of range "
        "(allowed: finite and >= 0)");
    for (const double vs : {0.0, -1e-3}) {
        expectThrowWithMessage<ParameterError>(
            [vs] { CoulombFriction f(frictionParameters(0.3, vs)); },
            "coulombFriction: parameter regularisationVelocity = "
                + connectors::formatValue(vs)
                + " m/s is out of range (allowed: finite and > 0)");
    }
    expectThrowWithMessage<ParameterError>(
        [] {
            CoulombFriction f(frictionParameters(
                0.3, std::numeric_limits<double>::infinity()));
        },
        "coulombFriction: parameter regularisationVelocity = inf m/s is out "
        "of range (allowed: finite and > 0)");
    expectThrowWithMessage<ParameterError>(
        [] {
            CoulombFriction f(
                frictionParameters(0.3, 1e-3, Vector3(1e-13, 0, 0)));
        },
        "coulombFriction: parameter B.axis = (1e-13, 0, 0) has no direction "
        "(allowed: (0, 0, 0) for friction in every direction, or a finite "
        "vector of length >= 1e-12, normalised by the law)");
    expectThrowWithMessage<ParameterError>(
        [] {
            CoulombFriction f(frictionParameters(
                0.3, 1e-3,
                Vector3(0, std::numeric_limits<double>::infinity(), 0)));
        },
        "coulombFriction: parameter B.axis[2] = inf is out of range "
        "(allowed: finite)");
    expectThrowWithMessage<ParameterError>(
        [] {
            CoulombFriction f(frictionParameters(
                0.3, 1e-3, Vector3::Zero(),
                Vector3(0, 0, std::numeric_limits<double>::infinity())));
        },
        "coulombFriction: parameter A.p[3] = inf m is out of range (allowed: "
        "finite)");
    expectNanInputRefused(
        CoulombFriction(frictionParameters(0.3, 1e-3)), &BodyKinematics::w_WK_W,
        0, "coulombFriction: input B.omega[1] = nan is not finite");
}

} // namespace

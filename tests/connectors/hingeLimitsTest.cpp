// connectors::Hinge at its limits: the angle through several full turns,
// opposite axes, coincident bodies, zero stiffness, derived reference
// directions, and the messages of bad parameters and inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "HingeTestSupport.hpp"
#include "common/ConnectorError.hpp"

namespace {

using namespace lawTest;
using connectors::ConnectorError;
using connectors::InputError;
using connectors::ParameterError;
using connectors::Refusal;

TEST(HingeLimits, AngleIsContinuousThroughSeveralTurns)
{
    // Five turns forward and back in steps of 0.3 rad (< pi), the angle fed
    // back as the FMU does: the output follows the accumulated rotation
    // with no jump at +-pi.
    const Hinge hinge(genericHinge());
    std::mt19937 rng(3);
    const BodyKinematics A = randomBody(rng);
    double previous = 0.0;
    double accumulated = 0.0;
    const int steps = int(5 * 2 * EIGEN_PI / 0.3);
    for (int i = 0; i < 2 * steps; ++i) {
        accumulated += i < steps ? 0.3 : -0.3;
        const HingeResult h = hinge.evaluate(
            A, hingedBody(hinge, A, accumulated, 0.0), previous);
        // Each step adds one rotation's round-off (~1e-15 rad); over 200
        // steps 1e-11 rad bounds it with a wide margin.
        ASSERT_NEAR(h.angle, accumulated, 1e-11) << "step " << i;
        EXPECT_LT(std::abs(h.angle - previous), 0.3 + 1e-11);
        previous = h.angle;
    }
    EXPECT_NEAR(previous, 0.0, 1e-11);
}

TEST(HingeLimits, UnwrapPicksTheNearestTurn)
{
    const double pi = EIGEN_PI;
    EXPECT_DOUBLE_EQ(connectors::unwrapAngle(-3.0, 3.0), 2 * pi - 3.0);
    EXPECT_DOUBLE_EQ(connectors::unwrapAngle(3.0, -3.0), 3.0 - 2 * pi);
    EXPECT_DOUBLE_EQ(connectors::unwrapAngle(0.5, 20 * pi + 0.4),
                     20 * pi + 0.5);
    EXPECT_EQ(connectors::unwrapAngle(1.0, 0.0), 1.0);
}

TEST(HingeLimits, OppositeAxesTurnBackAboutTheReferenceOfA)
{
    // B flipped by pi about y: a_B = -a_A = -z, theta = pi. The moment on B
    // is k_r pi e_A with e_A = x (derived from the z axis), finite, and
    // turning B by pi about x aligns the axes again.
    HingeParameters p;
    p.rotationalStiffness = 40.0;
    const Hinge hinge(p);
    const BodyKinematics A = body(Vector3::Zero());
    const BodyKinematics B
        = body(Vector3::Zero(), rotation(EIGEN_PI, Vector3::UnitY()));
    const HingeResult h = hinge.evaluate(A, B, 0.0);
    // sin(pi) = 1.2e-16 in the rotation: theta = pi to ~1e-16
    EXPECT_NEAR(h.misalignment, EIGEN_PI, 1e-15);
    expectVectorNear(h.loads.B.m_Ko_W, Vector3(40 * EIGEN_PI, 0, 0), 1e-12);
    expectVectorNear(h.loads.A.m_Ko_W, -h.loads.B.m_Ko_W, 0.0);
    EXPECT_NEAR(h.loads.potentialEnergy, 20 * EIGEN_PI * EIGEN_PI, 1e-12);
    expectAllFinite(h.loads);
    EXPECT_TRUE(std::isfinite(h.angle));

    // Just off the flip the moment keeps its magnitude k_r theta and turns
    // about the (now defined) a_B x a_A.
    const BodyKinematics near
        = body(Vector3::Zero(), rotation(EIGEN_PI - 1e-5, Vector3::UnitY()));
    const HingeResult hn = hinge.evaluate(A, near, 0.0);
    EXPECT_NEAR(hn.misalignment, EIGEN_PI - 1e-5, 1e-12);
    EXPECT_NEAR(hn.loads.B.m_Ko_W.norm(), 40 * (EIGEN_PI - 1e-5), 1e-10);
    expectVectorNear(hn.loads.B.m_Ko_W.normalized(), Vector3(0, -1, 0), 1e-9);
}

TEST(HingeLimits, CoincidentBodiesAndZeroStiffness)
{
    // Two bodies in the same place and pose with the hinge points at their
    // reference points: no gap, no misalignment, no load, nothing NaN.
    const Hinge hinge(HingeParameters {});
    HingeParameters stiff;
    stiff.stiffness = 1e6;
    stiff.rotationalStiffness = 1e4;
    const BodyKinematics A
        = body(Vector3(1, 2, 3), rotation(0.4, Vector3(1, 1, 0)));
    for (const Hinge& h : {hinge, Hinge(stiff)}) {
        const HingeResult r = h.evaluate(A, A, 0.0);
        expectAllFinite(r.loads);
        EXPECT_EQ(r.loads.A.f_W, Vector3::Zero());
        expectVectorNear(r.loads.A.m_Ko_W, Vector3::Zero(), 0.0);
        EXPECT_EQ(r.gap, 0.0);
        EXPECT_EQ(r.loads.lengthRate, 0.0);
        EXPECT_EQ(r.loads.tension, 0.0);
        EXPECT_EQ(r.misalignment, 0.0);
        EXPECT_EQ(r.angle, 0.0);
    }
    // Zero stiffness and damping: no load at any separation.
    std::mt19937 rng(11);
    const HingeResult r = hinge.evaluate(randomBody(rng), randomBody(rng), 0.0);
    EXPECT_EQ(r.loads.A.f_W, Vector3::Zero());
    EXPECT_EQ(r.loads.A.m_Ko_W, Vector3::Zero());
    EXPECT_EQ(r.loads.B.m_Ko_W, Vector3::Zero());
    EXPECT_EQ(r.loads.potentialEnergy, 0.0);
    EXPECT_GT(r.gap, 0.0);
}

TEST(HingeLimits, ReferenceDirections)
{
    using connectors::deriveReference;
    EXPECT_EQ(deriveReference(Vector3::UnitZ()), Vector3::UnitX());
    EXPECT_EQ(deriveReference(Vector3::UnitY()), Vector3::UnitX());
    EXPECT_EQ(deriveReference(Vector3::UnitX()), Vector3::UnitY());
    const Vector3 a = Vector3(1, 2, 2) / 3.0;
    const Vector3 e = deriveReference(a);
    EXPECT_NEAR(e.dot(a), 0.0, 1e-16);
    EXPECT_NEAR(e.norm(), 1.0, 1e-15);
    // A given reference loses its axial part and is normalised.
    HingeParameters p;
    p.axis_A = Vector3(0, 0, 2);
    p.ref_A = Vector3(0, 3, 5);
    const Hinge hinge(p);
    EXPECT_EQ(hinge.axisA(), Vector3::UnitZ());
    EXPECT_EQ(hinge.referenceA(), Vector3::UnitY());
}

TEST(HingeLimits, BadParametersAreNamed)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // The default parameters changed by `change`: refused as expectRefusal
    const auto refused = [](auto change, const std::string& message,
                            Refusal code, const std::string& parameter) {
        HingeParameters p;
        change(p);
        expectRefusal([&] { Hinge h(p); }, message, code, parameter);
    };
    refused(
        [](HingeParameters& p) { p.stiffness = -1.0; },
        "hinge: parameter stiffness = -1 N/m is out of range (allowed: finite "
        "and >= 0)",
        Refusal::negative, "stiffness");
    refused(
        [](HingeParameters& p) { p.rotationalDamping = -0.5; },
        "hinge: parameter rotationalDamping = -0.5 N.m.s/rad is out of range "
        "(allowed: finite and >= 0)",
        Refusal::negative, "rotationalDamping");
    refused([&](HingeParameters& p) { p.ptoDamping = nan; },
            "hinge: parameter ptoDamping = nan N.m.s/rad is out of range "
            "(allowed: finite and >= 0)",
            Refusal::notFinite, "ptoDamping");
    refused(
        [](HingeParameters& p) {
            p.ptoRestAngle = std::numeric_limits<double>::infinity();
        },
        "hinge: parameter ptoRestAngle = inf rad is out of range (allowed: "
        "finite)",
        Refusal::notFinite, "ptoRestAngle");
    refused(
        [&](HingeParameters& p) { p.axis_B[1] = nan; },
        "hinge: parameter B.axis[2] = nan is out of range (allowed: finite)",
        Refusal::notFinite, "B.axis[2]");
    refused([](HingeParameters& p) { p.axis_A = Vector3::Zero(); },
            "hinge: parameter A.axis = (0, 0, 0) has no direction (allowed: a "
            "finite "
            "vector of length >= 1e-12, normalised by the law)",
            Refusal::noDirection, "A.axis");
    refused(
        [](HingeParameters& p) {
            p.axis_B = Vector3(1, 0, 0);
            p.ref_B = Vector3(-2, 0, 0);
        },
        "hinge: parameter B.ref = (-2, 0, 0) is parallel to B.axis (allowed: a "
        "direction off the axis, or (0, 0, 0) to derive one)",
        Refusal::inconsistent, "B.ref");
}

TEST(HingeLimits, NonFiniteInputIsNamed)
{
    const Hinge hinge(genericHinge());
    BodyKinematics B = body(Vector3::Zero());
    B.w_WK_W[2] = std::numeric_limits<double>::infinity();
    expectThrowWithMessage<InputError>(
        [&] { hinge.evaluate(body(Vector3::Zero()), B, 0.0); },
        "hinge: input B.omega[3] = inf is not finite");
}

} // namespace

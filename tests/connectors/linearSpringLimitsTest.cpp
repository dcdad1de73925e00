// connectors::LinearSpring: parameter and input errors (exact messages) and
// the zero-length limit.
#include <gtest/gtest.h>

#include <limits>

#include "LawTestSupport.hpp"
#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"
#include "linearSpring/LinearSpring.hpp"

namespace {

using namespace lawTest;
using connectors::InputError;
using connectors::LinearSpring;
using connectors::LinearSpringParameters;
using connectors::ParameterError;
using connectors::UndefinedStateError;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

LinearSpringParameters valid()
{
    LinearSpringParameters p;
    p.stiffness = 100.0;
    p.restLength = 1.0;
    p.damping = 2.0;
    return p;
}

//- valid() changed by `change` is refused with `message`
template <class Change>
void expectRefused(Change&& change, const std::string& message)
{
    expectChangeRefused<LinearSpring, ParameterError>(valid(), change, message);
}

TEST(LinearSpringErrors, NegativeStiffness)
{
    expectRefused([](LinearSpringParameters& p) { p.stiffness = -1.0; },
                  "linearSpring: parameter stiffness = -1 N/m is out of range "
                  "(allowed: finite and >= 0)");
}

TEST(LinearSpringErrors, NegativeRestLength)
{
    expectRefused(
        [](LinearSpringParameters& p) { p.restLength = -0.25; },
        "linearSpring: parameter restLength = -0.25 m is out of range "
        "(allowed: finite and >= 0)");
}

TEST(LinearSpringErrors, NegativeDamping)
{
    expectRefused(
        [](LinearSpringParameters& p) { p.damping = -3.5; },
        "linearSpring: parameter damping = -3.5 N.s/m is out of range "
        "(allowed: finite and >= 0)");
}

TEST(LinearSpringErrors, NonFiniteParameters)
{
    expectRefused([](LinearSpringParameters& p) { p.stiffness = inf; },
                  "linearSpring: parameter stiffness = inf N/m is out of range "
                  "(allowed: finite and >= 0)");
    expectRefused([](LinearSpringParameters& p) { p.p_BoQ_B[1] = nan; },
                  "linearSpring: parameter B.p[2] = nan m is "
                  "out of range (allowed: finite)");
}

TEST(LinearSpringErrors, NonFiniteInputs)
{
    const LinearSpring spring(valid());
    BodyKinematics A = body(Vector3::Zero());
    BodyKinematics B = body(Vector3(2, 0, 0));
    A.R_WK(1, 2) = nan;
    expectThrowWithMessage<InputError>(
        [&] { spring.evaluate(A, B); },
        "linearSpring: input A.R[2,3] = nan is not finite");
    A = body(Vector3::Zero());
    B.w_WK_W[0] = -inf;
    expectThrowWithMessage<InputError>(
        [&] { spring.evaluate(A, B); },
        "linearSpring: input B.omega[1] = -inf is not finite");
    B = body(Vector3(2, 0, 0));
    B.p_WKo_W[2] = nan;
    expectThrowWithMessage<InputError>(
        [&] { spring.evaluate(A, B); },
        "linearSpring: input B.r[3] = nan is not finite");
}

TEST(LinearSpringZeroLength, ZeroRestLengthIsTheVectorLaw)
{
    // L0 = 0: f_A = k p_PQ at every length, including 0 and below 1e-12 m.
    LinearSpringParameters p = valid();
    p.restLength = 0.0;
    p.stiffness = 1e3;
    const LinearSpring spring(p);
    for (const Vector3& d : {Vector3(0, 0, 0), Vector3(3e-13, -4e-13, 0),
                             Vector3(1e-9, 2e-9, -2e-9), Vector3(0.5, 0, 0)}) {
        const ConnectorResult r
            = spring.evaluate(body(Vector3::Zero()), body(d));
        expectAllFinite(r);
        // One multiplication of exact inputs: equal up to 1 ulp.
        expectVectorNear(r.A.f_W, p.stiffness * d,
                         1e-15 * p.stiffness * d.norm());
        EXPECT_EQ(r.A.f_W, -r.B.f_W);
        EXPECT_NEAR(r.tension, p.stiffness * d.norm(),
                    1e-15 * p.stiffness * d.norm());
    }
}

TEST(LinearSpringZeroLength, DampingVanishesWhereTheAxisIsUndefined)
{
    // Below 1e-12 m dL/dt has no axis: lengthRate, the damping force and
    // the dissipated power are 0; above it damping acts along the axis.
    LinearSpringParameters p = valid();
    p.restLength = 0.0;
    const LinearSpring spring(p);
    const Vector3 v_B(0.3, -0.2, 0.1);
    const ConnectorResult below
        = spring.evaluate(body(Vector3::Zero()),
                          body(Vector3(5e-13, 0, 0), Matrix3::Identity(), v_B));
    expectAllFinite(below);
    EXPECT_EQ(below.lengthRate, 0.0);
    EXPECT_EQ(below.dissipatedPower, 0.0);
    // Only the elastic part k d remains (exact: one product).
    EXPECT_EQ(below.A.f_W, Vector3(p.stiffness * 5e-13, 0, 0));
    const ConnectorResult above
        = spring.evaluate(body(Vector3::Zero()),
                          body(Vector3(5e-12, 0, 0), Matrix3::Identity(), v_B));
    EXPECT_EQ(above.lengthRate, 0.3);
    // f_A,x = k L + c dL/dt = 100 * 5e-12 + 2 * 0.3; tolerance 1 ulp of 0.6.
    EXPECT_NEAR(above.A.f_W[0], 100.0 * 5e-12 + 0.6, 1e-16);
}

TEST(LinearSpringZeroLength, PositiveRestLengthIsAnError)
{
    const LinearSpring spring(valid());
    expectThrowWithMessage<UndefinedStateError>(
        [&] {
            spring.evaluate(body(Vector3(1, 1, 1)), body(Vector3(1, 1, 1)));
        },
        "linearSpring: length 0 m is below 1e-12 m with restLength = 1 m > 0: "
        "the spring force direction is undefined");
    // Just above the threshold the axis is defined again: |F| = k (L0 - L).
    const ConnectorResult r
        = spring.evaluate(body(Vector3::Zero()), body(Vector3(2e-12, 0, 0)));
    expectAllFinite(r);
    // Tolerance: 1e-12 relative to the 100 N force (round-off only).
    EXPECT_NEAR(r.A.f_W[0], -100.0 * (1.0 - 2e-12), 1e-10);
}

TEST(LinearSpringZeroLength, NoStiffnessMeansNoUndefinedForce)
{
    // k = 0 with L0 > 0 (a pure axial damper): nothing acts at zero length.
    LinearSpringParameters p = valid();
    p.stiffness = 0.0;
    const LinearSpring spring(p);
    const ConnectorResult r = spring.evaluate(
        body(Vector3::Zero()),
        body(Vector3::Zero(), Matrix3::Identity(), Vector3(1, 2, 3)));
    expectAllFinite(r);
    EXPECT_EQ(r.A.f_W, Vector3::Zero());
    EXPECT_EQ(r.potentialEnergy, 0.0);
}

} // namespace

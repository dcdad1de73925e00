// Helpers for the connector law tests: kinematics builders and the balance
// checks that every two-point connector must satisfy.
#ifndef TESTS_CONNECTORS_LAWTESTSUPPORT_HPP
#define TESTS_CONNECTORS_LAWTESTSUPPORT_HPP

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <limits>
#include <random>
#include <string>

#include "common/ConnectorError.hpp"
#include "common/Kinematics.hpp"

namespace lawTest {

using connectors::BodyKinematics;
using connectors::ConnectorResult;
using connectors::Matrix3;
using connectors::Vector3;

inline constexpr double pi = 3.14159265358979323846;

inline Matrix3 rotation(double angle, const Vector3& axis)
{
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

inline BodyKinematics body(const Vector3& r,
                           const Matrix3& R = Matrix3::Identity(),
                           const Vector3& v = Vector3::Zero(),
                           const Vector3& omega = Vector3::Zero())
{
    return {r, R, v, omega}; // p_WKo_W, R_WK, v_WKo_W, w_WK_W
}

//- A body with random position, orientation and velocities (fixed seed)
inline BodyKinematics randomBody(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    const Vector3 axis(u(rng), u(rng), u(rng));
    return body(Vector3(u(rng), u(rng), u(rng)), rotation(u(rng), axis),
                Vector3(u(rng), u(rng), u(rng)),
                Vector3(u(rng), u(rng), u(rng)));
}

//- Power delivered by the connector to both bodies [W]:
//  f_A . v_Ao + m_A . w_A + f_B . v_Bo + m_B . w_B
inline double powerIntoBodies(const ConnectorResult& r, const BodyKinematics& A,
                              const BodyKinematics& B)
{
    return r.A.f_W.dot(A.v_WKo_W) + r.A.m_Ko_W.dot(A.w_WK_W)
        + r.B.f_W.dot(B.v_WKo_W) + r.B.m_Ko_W.dot(B.w_WK_W);
}

//- Total moment of the loads on A and B about the global origin [N.m]
inline Vector3 totalMomentAboutOrigin(const ConnectorResult& r,
                                      const BodyKinematics& A,
                                      const BodyKinematics& B)
{
    return A.p_WKo_W.cross(r.A.f_W) + r.A.m_Ko_W + B.p_WKo_W.cross(r.B.f_W)
        + r.B.m_Ko_W;
}

inline void expectVectorNear(const Vector3& actual, const Vector3& expected,
                             double tolerance)
{
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(actual[i], expected[i], tolerance) << "component " << i;
    }
}

inline void expectAllFinite(const ConnectorResult& r)
{
    EXPECT_TRUE(r.A.f_W.allFinite() && r.A.m_Ko_W.allFinite()
                && r.B.f_W.allFinite() && r.B.m_Ko_W.allFinite());
    EXPECT_TRUE(std::isfinite(r.length) && std::isfinite(r.lengthRate)
                && std::isfinite(r.tension) && std::isfinite(r.potentialEnergy)
                && std::isfinite(r.dissipatedPower));
}

//- Solves miss(x, y) = 0, two equations (a 2-vector), from (x, y) by
//  Newton's method with a difference Jacobian of steps (dx, dy) =
//  steps(x, y), each step halved (down to 1e-6 of it) until |miss|
//  decreases with x > 0. True when |miss| < tolerance within `iterations`.
template <class Miss, class Steps>
bool dampedNewton(const Miss& miss, const Steps& steps, double tolerance,
                  int iterations, double& x, double& y)
{
    for (int iteration = 0; iteration < iterations; ++iteration) {
        const Eigen::Vector2d r = miss(x, y);
        if (r.norm() < tolerance) {
            return true;
        }
        const Eigen::Vector2d d = steps(x, y);
        Eigen::Matrix2d J;
        J.col(0) = (miss(x + d[0], y) - r) / d[0];
        J.col(1) = (miss(x, y + d[1]) - r) / d[1];
        const Eigen::Vector2d step = -J.fullPivLu().solve(r);
        double a = 1.0;
        while (
            a > 1e-6
            && !(x + a * step[0] > 0.0
                 && miss(x + a * step[0], y + a * step[1]).norm() < r.norm())) {
            a *= 0.5;
        }
        x += a * step[0];
        y += a * step[1];
    }
    return false;
}

//- Runs `call`, expects it to throw `Exception` with exactly `message`
template <class Exception, class Call>
void expectThrowWithMessage(Call&& call, const std::string& message)
{
    try {
        call();
        ADD_FAILURE() << "no exception, expected: " << message;
    } catch (const Exception& e) {
        EXPECT_EQ(std::string(e.what()), message);
    }
}

//- law.evaluate(A at the origin, B at (1, 0, 0) with component `i` of its
//  member `field` NaN) throws InputError with `message`
template <class Law>
void expectNanInputRefused(const Law& law, Vector3 BodyKinematics::*field,
                           int i, const std::string& message)
{
    BodyKinematics B = body(Vector3(1, 0, 0));
    (B.*field)[i] = std::numeric_limits<double>::quiet_NaN();
    expectThrowWithMessage<connectors::InputError>(
        [&] { law.evaluate(body(Vector3::Zero()), B); }, message);
}

//- A `Law` made of `parameters` changed by `change` throws `Exception` with
//  exactly `message`
template <class Law, class Exception, class Parameters, class Change>
void expectChangeRefused(Parameters parameters, Change&& change,
                         const std::string& message)
{
    change(parameters);
    expectThrowWithMessage<Exception>([&] { Law law(parameters); }, message);
}

//- call() throws ParameterError with `message`, `code` and `parameter`
template <class Call>
void expectRefusal(Call&& call, const std::string& message,
                   connectors::Refusal code, const std::string& parameter)
{
    try {
        call();
        ADD_FAILURE() << "no exception, expected: " << message;
    } catch (const connectors::ParameterError& e) {
        EXPECT_EQ(std::string(e.what()), message);
        EXPECT_EQ(connectors::refusalName(e.code()),
                  std::string(connectors::refusalName(code)))
            << message;
        EXPECT_EQ(e.parameter(), parameter) << message;
    }
}

//- `message` starts with `start` and contains `part`
inline void expectStartsWithAndContains(const std::string& message,
                                        const std::string& start,
                                        const std::string& part)
{
    EXPECT_EQ(message.rfind(start, 0), 0u) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
}

} // namespace lawTest

#endif

#include "twobody/RigidBody.hpp"

#include <cmath>

namespace fmusim {

namespace {

// Angular acceleration in the global frame: J_g domega/dt = M - omega x (J_g omega), J_g = R J R^T.
Eigen::Vector3d angularAcceleration(const Body& body,
                                    const Eigen::Quaterniond& q,
                                    const Eigen::Vector3d& omega,
                                    const Eigen::Vector3d& M)
{
    const Eigen::Matrix3d R = q.toRotationMatrix();
    const Eigen::Matrix3d J = R * body.inertia * R.transpose();
    return J.ldlt().solve(M - omega.cross(J * omega));
}

} // namespace

Eigen::Quaterniond rotationFromVector(const Eigen::Vector3d& phi)
{
    const double angle = phi.norm();
    if (angle < 1e-300)
        return Eigen::Quaterniond::Identity();
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, phi / angle));
}

BodyState prescribedState(const Body& body, double t)
{
    BodyState s = body.initial;
    if (body.motion == MotionKind::world)
        return BodyState();
    s.v.setZero();
    s.omega.setZero();
    if (body.motion != MotionKind::sinusoidal)
        return s;
    const double w = 2 * M_PI * body.frequency;
    const double sine = std::sin(w * t + body.phase),
                 cosine = std::cos(w * t + body.phase);
    s.x = body.initial.x + body.amplitude * sine;
    s.v = body.amplitude * w * cosine;
    s.q = (rotationFromVector(body.rotationAmplitude * sine) * body.initial.q)
              .normalized();
    s.omega
        = body.rotationAmplitude * w * cosine; // rotation about a fixed axis
    return s;
}

Kinematics kinematicsOf(const BodyState& s)
{
    Kinematics k;
    k.r = s.x;
    k.R = s.q.toRotationMatrix();
    k.v = s.v;
    k.omega = s.omega;
    return k;
}

MassProperties massPropertiesOf(const Body& body)
{
    MassProperties p;
    p.m = body.mass;
    p.J = body.inertia;
    return p;
}

double kineticEnergy(const Body& body, const BodyState& s)
{
    if (body.motion == MotionKind::world)
        return 0;
    const Eigen::Matrix3d R = s.q.toRotationMatrix();
    return 0.5 * body.mass * s.v.squaredNorm()
        + 0.5 * s.omega.dot(R * body.inertia * R.transpose() * s.omega);
}

BodyState explicitStep(const Body& body, const BodyState& s0,
                       const Loads& loads0, const Eigen::Vector3d& gravity,
                       double h)
{
    BodyState s1;
    s1.v = s0.v + h * (loads0.F / body.mass + gravity);
    s1.x = s0.x + h * s1.v;
    s1.omega
        = s0.omega + h * angularAcceleration(body, s0.q, s0.omega, loads0.M);
    s1.q = (rotationFromVector(h * s1.omega) * s0.q).normalized();
    return s1;
}

BodyState trapezoidalStep(const Body& body, const BodyState& s0,
                          const Loads& loads0, const Loads& loads1,
                          const Eigen::Vector3d& gravity, double h)
{
    BodyState s1;
    s1.v = s0.v + 0.5 * h * ((loads0.F + loads1.F) / body.mass + 2 * gravity);
    s1.x = s0.x + 0.5 * h * (s0.v + s1.v);
    const Eigen::Vector3d alpha0
        = angularAcceleration(body, s0.q, s0.omega, loads0.M);
    s1.omega = s0.omega + h * alpha0;
    for (int iteration = 0; iteration < 100; ++iteration) {
        s1.q = (rotationFromVector(0.5 * h * (s0.omega + s1.omega)) * s0.q)
                   .normalized();
        const Eigen::Vector3d omega = s0.omega
            + 0.5 * h
                * (alpha0
                   + angularAcceleration(body, s1.q, s1.omega, loads1.M));
        const double change = (omega - s1.omega).norm();
        s1.omega = omega;
        if (change <= 1e-15 * (1 + omega.norm()))
            break;
    }
    s1.q = (rotationFromVector(0.5 * h * (s0.omega + s1.omega)) * s0.q)
               .normalized();
    return s1;
}

} // namespace fmusim

// Rigid bodies for `fmusim twobody`: state, prescribed motion, and the
// explicit and trapezoidal updates. Reference point = centre of mass;
// velocities and angular velocities in the global frame.
#ifndef FMUSIM_TWOBODY_RIGIDBODY_HPP
#define FMUSIM_TWOBODY_RIGIDBODY_HPP

#include "io/ConnectorIo.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>

namespace fmusim {

struct BodyState {
    Eigen::Vector3d x
        = Eigen::Vector3d::Zero(); // position of the centre of mass [m]
    Eigen::Quaterniond q
        = Eigen::Quaterniond::Identity(); // orientation, body to global
    Eigen::Vector3d v = Eigen::Vector3d::Zero(); // velocity [m/s]
    Eigen::Vector3d omega
        = Eigen::Vector3d::Zero(); // angular velocity, global frame [rad/s]
};

enum class MotionKind { free, fixed, sinusoidal, world };

struct Body {
    MotionKind motion = MotionKind::free;
    double mass = 1; // [kg]
    Eigen::Matrix3d inertia = Eigen::Matrix3d::
        Identity(); // about the centre of mass, body frame [kg.m2]
    BodyState initial;
    // Sinusoidal motion: x = x0 + amplitude sin(2 pi f t + phase),
    // R = exp(rotationAmplitude sin(2 pi f t + phase)) R0.
    Eigen::Vector3d amplitude = Eigen::Vector3d::Zero(); // [m]
    Eigen::Vector3d rotationAmplitude
        = Eigen::Vector3d::Zero(); // rotation vector [rad]
    double frequency = 0; // [Hz]
    double phase = 0; // [rad]

    bool isFree() const { return motion == MotionKind::free; }
};

// The state of a body whose motion is prescribed (fixed, sinusoidal, world).
BodyState prescribedState(const Body& body, double t);

Kinematics kinematicsOf(const BodyState& s);

MassProperties massPropertiesOf(const Body& body);

// 0.5 m v.v + 0.5 omega.(R J R^T) omega [J]
double kineticEnergy(const Body& body, const BodyState& s);

// Unit quaternion of the rotation vector phi (the exponential map).
Eigen::Quaterniond rotationFromVector(const Eigen::Vector3d& phi);

// Semi-implicit (symplectic) Euler with the loads at the start of the step:
// v1 = v0 + h (F/m + g), x1 = x0 + h v1; omega1 = omega0 + h alpha(q0,
// omega0, M), q1 = exp(h omega1) q0.
BodyState explicitStep(const Body& body, const BodyState& s0,
                       const Loads& loads0, const Eigen::Vector3d& gravity,
                       double h);

// Trapezoidal rule with the loads at both ends of the step:
// v1 = v0 + h/2 (a0 + a1), x1 = x0 + h/2 (v0 + v1), omega likewise with the
// angular accelerations, q1 = exp(h (omega0 + omega1)/2) q0; the
// gyroscopic term at the end of the step is iterated to round-off.
BodyState trapezoidalStep(const Body& body, const BodyState& s0,
                          const Loads& loads0, const Loads& loads1,
                          const Eigen::Vector3d& gravity, double h);

} // namespace fmusim

#endif

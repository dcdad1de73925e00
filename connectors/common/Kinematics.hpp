// Body kinematics and connector loads shared by every connector law.
//
// Frames and points (Drake-style monogram notation):
//   W      the global (inertial) frame and its origin,
//   A, B   the body-fixed frames of the two bodies,
//   Ao, Bo the reference points of A and B (origins of their frames),
//   P      the attachment point on A, Q the attachment point on B,
//   K, Ko  whichever body a BodyKinematics or BodyLoads describes (A or
//          B) and its reference point.
// p_XY_Z is the position of point Y from point X expressed in frame Z,
// v_XY_Z a velocity, w_XY_Z an angular velocity, R_XY a rotation matrix
// taking vectors in frame Y to frame X. Everything is in SI units.
#ifndef CONNECTORS_COMMON_KINEMATICS_HPP
#define CONNECTORS_COMMON_KINEMATICS_HPP

#include <Eigen/Core>

namespace connectors {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

//- Kinematics of one rigid body (FMU inputs r, R, v, omega)
struct BodyKinematics {
    //- Position of the body's reference point Ko from W, global frame [m]
    Vector3 p_WKo_W = Vector3::Zero();
    //- Orientation, body frame to global frame: x_W = p_WKo_W + R_WK x_K [-]
    Matrix3 R_WK = Matrix3::Identity();
    //- Velocity of the reference point Ko in W, global frame [m/s]
    Vector3 v_WKo_W = Vector3::Zero();
    //- Angular velocity of the body in W, global frame [rad/s]
    Vector3 w_WK_W = Vector3::Zero();
};

//- Load of the connector on one body (FMU outputs F, M)
struct BodyLoads {
    //- Force on the body, global frame [N]
    Vector3 f_W = Vector3::Zero();
    //- Moment on the body about its reference point Ko, global frame [N.m]
    Vector3 m_Ko_W = Vector3::Zero();
};

//- Everything a law returns: loads on both bodies and the diagnostics
struct ConnectorResult {
    //- Load on body A
    BodyLoads A;
    //- Load on body B
    BodyLoads B;
    //- Distance between the attachment points [m]
    double length = 0.0;
    //- Time derivative of the length [m/s]
    double lengthRate = 0.0;
    //- Axial force, positive when the connector pulls A and B together [N]
    double tension = 0.0;
    //- Energy stored in the connector [J]
    double potentialEnergy = 0.0;
    //- Power dissipated by the connector (removed from the bodies and not
    //  stored), >= 0 [W]
    double dissipatedPower = 0.0;
};

//- A connector law: both bodies' kinematics to the loads on both bodies.
//  Implementations validate their parameters on construction and their
//  inputs on every evaluation (throwing ParameterError / InputError /
//  UndefinedStateError, see ConnectorError.hpp); they never return NaN.
class ConnectorLaw {
public:
    virtual ~ConnectorLaw() = default;

    //- Loads and diagnostics for the given kinematics of A and B
    virtual ConnectorResult evaluate(const BodyKinematics& A,
                                     const BodyKinematics& B) const = 0;
};

} // namespace connectors

#endif

// Tabulated axial angular spring: OpenFOAM's sixDoF
// tabulatedAxialAngularSpring restraint (v1912, v2312) between bodies A and
// B, a moment about an axis fixed in B looked up in a table of (angle,
// moment) points from A's turn about that axis away from a reference
// orientation, computed as OpenFOAM computes it; to the fixed world (B at
// rest, identity) it is that restraint.
//
// In B's frame, with n the unit axis, R = R_WB^T R_WA A's orientation
// relative to B and Q0 its reference orientation, theta is the angle of
// linearAxialAngularSpring (common/AxialAngle.hpp) with its sign:
//
//   theta = magnitude sign(sense), sign(s) = 1 for s >= 0, else -1  [rad]
//   x = theta (angleInDegrees = 0) or theta 180/pi (= 1)            [rad, deg]
//   M(x): the table's value at x (MomentTable.hpp, with outOfBounds) [N.m]
//   w_rel = R_WB^T (w_A - w_B)                                      [rad/s]
//   moment on A: m_A = R_WB ((M(x) - c (w_rel . n)) n), m_B = -m_A  [N.m]
//   forces 0; length, lengthRate between A.p and B.p (diagnostics)
//   tension 0, potential energy E = -(integral of M from 0 to x) dtheta/dx
//     [J], dissipated power c (w_rel . n)^2 >= 0 [W]
//
// A moment that turns A back has the sign opposite to the angle's: the
// table (-1 1) (1 -1) in radians is linearAxialAngularSpring with
// k = 1 N.m/rad. For turns about n the power into the bodies is exactly
// -dE/dt - dissipatedPower; a turn about another axis changes theta
// without work, the switch of OpenFOAM's reference direction is a jump of
// theta, and theta jumps from pi to -pi where A turns through the
// opposite of its reference: there E jumps by the integral of M over the
// turn, as OpenFOAM's moment does not derive from one energy there.
//
// outOfBounds error refuses an angle outside the table with
// UndefinedStateError; warn gives clamp's values (a law has no warning
// channel). c [N.m.s/rad] finite and >= 0; the table as MomentTable; the
// axis finite and not zero (it is normalised); the reference orientation
// finite and, as OpenFOAM reads it, of norm sqrt(3) within 3.2e-8
// (ParameterError otherwise). Non-finite inputs throw InputError.
// No output is NaN.
#ifndef CONNECTORS_TABULATEDAXIALANGULARSPRING_TABULATEDAXIALANGULARSPRING_HPP
#define CONNECTORS_TABULATEDAXIALANGULARSPRING_TABULATEDAXIALANGULARSPRING_HPP

#include <vector>

#include "common/Kinematics.hpp"
#include "tabulatedAxialAngularSpring/MomentTable.hpp"

namespace connectors {

struct TabulatedAxialAngularSpringParameters {
    //- Point P on A, A's frame, that length is measured from [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Point Q on B, B's frame, that length is measured to [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- The axis n, B's frame (normalised by the law) [-]
    Vector3 axis_B = Vector3::UnitZ();
    //- Reference orientation Q0 of A relative to B (A's frame to B's) [-]
    Matrix3 R_BA0 = Matrix3::Identity();
    //- The table's angles, strictly increasing [rad, deg with
    //  angleInDegrees]
    std::vector<double> angle = {-1.0, 1.0};
    //- The moment about n on A at each angle [N.m]
    std::vector<double> moment = {0.0, 0.0};
    //- Whether the table's angles are in degrees (OpenFOAM's angleFormat)
    bool angleInDegrees = false;
    //- Outside the table's angles, as OpenFOAM's outOfBounds
    OutOfBounds outOfBounds = OutOfBounds::clamp;
    //- Damping c [N.m.s/rad]
    double damping = 0.0;
};

class TabulatedAxialAngularSpring final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit TabulatedAxialAngularSpring(
        const TabulatedAxialAngularSpringParameters& parameters);

    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    const TabulatedAxialAngularSpringParameters& parameters() const
    {
        return parameters_;
    }

private:
    TabulatedAxialAngularSpringParameters parameters_;
    //- The unit axis, B's frame
    Vector3 n_B_;
    MomentTable table_;
    //- The table's integral from its first angle to angle 0
    double integralToZero_;
};

} // namespace connectors

#endif

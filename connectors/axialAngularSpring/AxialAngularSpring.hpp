// Axial angular spring: OpenFOAM's sixDoF linearAxialAngularSpring
// restraint (v1912, v2312) between bodies A and B, a moment about an axis
// fixed in B that turns A back towards a reference orientation, computed
// as OpenFOAM computes it; to the fixed world (B at rest, identity) it is
// that restraint.
//
// In B's frame, with n the unit axis, R = R_WB^T R_WA A's orientation
// relative to B and Q0 its reference orientation:
//
//   d = T e_y, T = rotationTensor(e_x, n) (OpenFOAM's: turns e_x onto n);
//     d = T e_z where |n . Q0 d| > 0.95 or |n . R d| > 0.95
//   u = Q0 d, w = R d, each less its part along n, normalised
//   theta = |acos(min(max(u . w, -1), 1))|                         [rad]
//   a = n sign((u x w) . n) (0 where (u x w) . n = 0)
//   w_rel = R_WB^T (w_A - w_B)                                     [rad/s]
//   moment on A: m_A = R_WB (-(k theta + c (w_rel . a)) a), m_B = -m_A  [N.m]
//   forces 0; length, lengthRate between A.p and B.p (diagnostics)
//   tension 0, potential energy k theta^2 / 2 [J],
//   dissipated power c (w_rel . a)^2 >= 0 [W]
//
// theta is the angle of A about n from its reference as far as turning
// about n goes: for turns about n the power into the bodies is exactly
// -d(energy)/dt - dissipatedPower; a turn about another axis changes theta
// without work, as in OpenFOAM. The switch of d is a jump of the moment,
// as in OpenFOAM. OpenFOAM takes acos of min(u . w, 1) only (NaN just
// beyond -1 by round-off); here u . w is also held above -1.
//
// k [N.m/rad], c [N.m.s/rad] finite and >= 0; the axis finite and not zero
// (it is normalised); the reference orientation finite and, as OpenFOAM
// reads it, of norm sqrt(3) within 3.2e-8 (ParameterError otherwise). Non-finite inputs throw InputError. No output is NaN.
#ifndef CONNECTORS_AXIALANGULARSPRING_AXIALANGULARSPRING_HPP
#define CONNECTORS_AXIALANGULARSPRING_AXIALANGULARSPRING_HPP

#include "common/Kinematics.hpp"

namespace connectors {

struct AxialAngularSpringParameters {
    //- Point P on A, A's frame, that length is measured from [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Point Q on B, B's frame, that length is measured to [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- The axis n, B's frame (normalised by the law) [-]
    Vector3 axis_B = Vector3::UnitZ();
    //- Reference orientation Q0 of A relative to B (A's frame to B's) [-]
    Matrix3 R_BA0 = Matrix3::Identity();
    //- Stiffness k [N.m/rad]
    double stiffness = 0.0;
    //- Damping c [N.m.s/rad]
    double damping = 0.0;
};

class AxialAngularSpring final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit AxialAngularSpring(const AxialAngularSpringParameters& parameters);

    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    const AxialAngularSpringParameters& parameters() const
    {
        return parameters_;
    }

private:
    AxialAngularSpringParameters parameters_;
    //- The unit axis, B's frame
    Vector3 n_B_;
};

} // namespace connectors

#endif

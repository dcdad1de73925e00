// Spherical angular spring: OpenFOAM's sixDoF sphericalAngularSpring
// restraint (v1912, v2312) between bodies A and B, a moment that turns A
// back towards a reference orientation relative to B about every axis,
// computed as OpenFOAM computes it; to the fixed world (B at rest,
// identity) it is that restraint.
//
// In B's frame, with R = R_WB^T R_WA A's orientation relative to B and Q0
// its reference orientation:
//
//   for i = 1, 2, 3 and j = i + 1 (3 + 1 = 1):
//     a = Q0 e_i,  r = Q0 e_j,  d = R e_j - (a . R e_j) a
//     m += -k (r x d)                                              [N.m]
//   w_rel = R_WB^T (w_A - w_B)                                     [rad/s]
//   moment on A: m_A = R_WB (m - c w_rel), m_B = -m_A              [N.m]
//   forces 0; length, lengthRate between A.p and B.p (diagnostics)
//   tension 0, potential energy k (1 - cos theta) = k |R - Q0|^2 / 4 [J]
//   (theta the angle of Q0^T R), dissipated power c |w_rel|^2 >= 0 [W]
//
// The moment is not conservative at finite angles. With n the unit axis of
// Q0^T R, in the reference frame Q0,
//   m = -k sin(theta) n - k (1 - cos theta) (n_y n_z, n_z n_x, n_x n_y):
// the first term is minus the gradient of the potential energy, the second
// does work around closed loops of rotations. So the power into the bodies
// is -d(energy)/dt - dissipatedPower plus that term's power, at most
// k (1 - cos theta) |w_rel| / sqrt(3): exact for turns about an axis of
// the reference frame, of relative order theta for small turns about
// others (connectors/sphericalAngularSpring/README.md).
//
// k [N.m/rad], c [N.m.s/rad] finite and >= 0; the reference orientation
// finite and, as OpenFOAM reads it, of norm sqrt(3) within 3.2e-8
// (ParameterError otherwise). Non-finite inputs throw InputError. No
// output is NaN.
#ifndef CONNECTORS_SPHERICALANGULARSPRING_SPHERICALANGULARSPRING_HPP
#define CONNECTORS_SPHERICALANGULARSPRING_SPHERICALANGULARSPRING_HPP

#include "common/Kinematics.hpp"

namespace connectors {

struct SphericalAngularSpringParameters {
    //- Point P on A, A's frame, that length is measured from [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Point Q on B, B's frame, that length is measured to [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Reference orientation Q0 of A relative to B (A's frame to B's) [-]
    Matrix3 R_BA0 = Matrix3::Identity();
    //- Stiffness k [N.m/rad]
    double stiffness = 0.0;
    //- Damping c [N.m.s/rad]
    double damping = 0.0;
};

class SphericalAngularSpring final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit SphericalAngularSpring(
        const SphericalAngularSpringParameters& parameters);

    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    const SphericalAngularSpringParameters& parameters() const
    {
        return parameters_;
    }

private:
    SphericalAngularSpringParameters parameters_;
};

} // namespace connectors

#endif

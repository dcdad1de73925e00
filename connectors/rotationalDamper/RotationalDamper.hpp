// Rotational damper between bodies A and B: a linear viscous moment on the
// angular velocity of B relative to A, about every axis (OpenFOAM's
// built-in sphericalAngularDamper restraint, M = -c omega, is this
// connector with B the fixed world).
//
// With w_rel = w_B - w_A:
//
//   moments (pure couples):  m_A = +c w_rel,  m_B = -m_A           [N.m]
//   forces:                  f_A = f_B = 0                         [N]
//   length L = |Q - P| between the points A.p and B.p, lengthRate
//     dL/dt (diagnostics only)                                     [m, m/s]
//   tension 0, potential energy 0,
//   dissipated power D = c |w_rel|^2 >= 0                          [W]
//
// c [N.m.s/rad] must be finite and >= 0 (ParameterError otherwise). Below
// a length of minimumAxisLength (1e-12 m) lengthRate is 0. Non-finite
// inputs throw InputError. No output is NaN.
#ifndef CONNECTORS_ROTATIONALDAMPER_ROTATIONALDAMPER_HPP
#define CONNECTORS_ROTATIONALDAMPER_ROTATIONALDAMPER_HPP

#include "common/Kinematics.hpp"

namespace connectors {

struct RotationalDamperParameters {
    //- Point P on A, A's frame, from A's reference point, that length is
    //  measured from (no effect on the loads) [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Point Q on B, B's frame, from B's reference point, that length is
    //  measured to (no effect on the loads) [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Damping coefficient c [N.m.s/rad]
    double damping = 0.0;
};

class RotationalDamper final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit RotationalDamper(const RotationalDamperParameters& parameters);

    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    const RotationalDamperParameters& parameters() const { return parameters_; }

private:
    RotationalDamperParameters parameters_;
};

} // namespace connectors

#endif

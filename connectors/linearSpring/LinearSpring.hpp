// Linear spring with optional linear damping along its axis.
//
// With P fixed in A, Q fixed in B, L = |p_PQ| the length, e = p_PQ / L the
// unit vector from P to Q and dL/dt = e . (v_WQ - v_WP):
//
//   tension T = k (L - L0) + c dL/dt                          [N]
//   force on A at P:  f_A = +T e,  force on B at Q:  f_B = -T e
//   moments:  m_A = p_AoP_W x f_A,  m_B = p_BoQ_W x f_B      [N.m]
//   potential energy  V = k (L - L0)^2 / 2                   [J]
//   dissipated power  D = c (dL/dt)^2 >= 0                   [W]
//
// A stretched spring (T > 0) pulls A towards B. k [N/m], L0 [m] and
// c [N.s/m] must be finite and >= 0 (ParameterError otherwise).
//
// Zero length (L < minimumAxisLength = 1e-12 m, axis undefined):
//  - L0 = 0: the elastic force is the vector k p_PQ (well defined, no axis
//    needed; the same formula is used at every length when L0 = 0);
//  - L0 > 0 and k > 0: the force k (L - L0) e has a finite magnitude and no
//    direction: UndefinedStateError;
//  - the damping term c (dL/dt) e also needs the axis: below 1e-12 m it is
//    taken as zero, and lengthRate and dissipatedPower are reported as 0.
// Non-finite inputs throw InputError. No output is ever NaN.
#ifndef CONNECTORS_LINEARSPRING_LINEARSPRING_HPP
#define CONNECTORS_LINEARSPRING_LINEARSPRING_HPP

#include "common/Kinematics.hpp"

namespace connectors {

struct LinearSpringParameters {
    //- Attachment point P on A, A's frame, from A's reference point [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Attachment point Q on B, B's frame, from B's reference point [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Stiffness k [N/m]
    double stiffness = 0.0;
    //- Rest length L0 [m]
    double restLength = 0.0;
    //- Axial damping coefficient c [N.s/m]
    double damping = 0.0;
};

class LinearSpring final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit LinearSpring(const LinearSpringParameters& parameters);

    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    const LinearSpringParameters& parameters() const { return parameters_; }

private:
    LinearSpringParameters parameters_;
};

} // namespace connectors

#endif

// Linear damper between an attachment point P fixed in A and Q fixed in B.
//
// With e the unit vector from P to Q and v_PQ = v_WQ - v_WP the velocity of
// Q relative to P:
//
//   lengthRate dL/dt = e . v_PQ                               [m/s]
//   tension    T = c dL/dt                                    [N]
//   force on A at P: f_A = +T e, force on B at Q: f_B = -c (v_PQ . e) e
//   moments:  m_A = p_AoP_W x f_A,  m_B = p_BoQ_W x f_B      [N.m]
//   potential energy 0, dissipated power D = c (dL/dt)^2 >= 0 [W]
//
// c [N.s/m] must be finite and >= 0 (ParameterError otherwise).
// Zero length (L < minimumAxisLength = 1e-12 m): the axis is undefined, the
// force is taken as zero and lengthRate, tension and dissipatedPower are 0.
// Non-finite inputs throw InputError. No output is ever NaN.
#ifndef CONNECTORS_LINEARDAMPER_LINEARDAMPER_HPP
#define CONNECTORS_LINEARDAMPER_LINEARDAMPER_HPP

#include "common/Kinematics.hpp"

namespace connectors {

struct LinearDamperParameters {
    //- Attachment point P on A, A's frame, from A's reference point [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Attachment point Q on B, B's frame, from B's reference point [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Damping coefficient c [N.s/m]
    double damping = 0.0;
};

class LinearDamper final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit LinearDamper(const LinearDamperParameters& parameters);

    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    const LinearDamperParameters& parameters() const { return parameters_; }

private:
    LinearDamperParameters parameters_;
};

} // namespace connectors

#endif

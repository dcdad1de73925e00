// Translational damper at a point P fixed in A: a linear viscous force on
// the velocity of B's material point at P relative to A's, in every
// direction (OpenFOAM's built-in linearDamper restraint, F = -c v, is this
// connector with P at the body's reference point and B the fixed world).
//
// With p_P_W = p_WAo + R_WA p_AoP_A the point P and
// v_rel = (v_WBo + w_B x (p_P_W - p_WBo)) - (v_WAo + w_A x p_AoP_W):
//
//   force on A at P: f_A = +c v_rel,  force on B at P: f_B = -f_A   [N]
//   moments:  m_A = p_AoP_W x f_A,  m_B = (p_P_W - p_WBo) x f_B     [N.m]
//   length L = |Q - P|, lengthRate dL/dt = e . (v_Q - v_P), with Q
//     the point B.p of B and e = (Q - P)/L (diagnostics only)       [m, m/s]
//   tension T = f_A . e (the force's component along P->Q)          [N]
//   potential energy 0, dissipated power D = c |v_rel|^2 >= 0       [W]
//
// Both forces act at P, so the pair has no moment about any point, and the
// power into the bodies is exactly -D. c [N.s/m] must be finite and >= 0
// (ParameterError otherwise). Below a length of minimumAxisLength
// (1e-12 m) the axis is undefined: lengthRate and tension are 0, the force
// is not affected. Non-finite inputs throw InputError. No output is NaN.
#ifndef CONNECTORS_TRANSLATIONALDAMPER_TRANSLATIONALDAMPER_HPP
#define CONNECTORS_TRANSLATIONALDAMPER_TRANSLATIONALDAMPER_HPP

#include "common/Kinematics.hpp"

namespace connectors {

struct TranslationalDamperParameters {
    //- Attachment point P on A, A's frame, from A's reference point [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Point Q on B, B's frame, from B's reference point, that length is
    //  measured to (no effect on the loads) [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Damping coefficient c [N.s/m]
    double damping = 0.0;
};

class TranslationalDamper final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit TranslationalDamper(
        const TranslationalDamperParameters& parameters);

    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    const TranslationalDamperParameters& parameters() const
    {
        return parameters_;
    }

private:
    TranslationalDamperParameters parameters_;
};

} // namespace connectors

#endif

// Regularised Coulomb friction between a point P fixed in A sliding on body
// B (a guide, a floor) or on the fixed world.
//
// The contact is at P. With v_s the regularisation velocity, F_c the
// Coulomb (sliding) force and, in the global frame,
//
//   u   = v_WP - v_WB(P)   velocity of A's point P relative to the point of
//                          B at P (B's material velocity there)      [m/s]
//   a   = R_WB a_B / |a_B| the guide direction, turned with B        [-]
//   u_t = (a . u) a        along the guide; u_t = u when a_B = 0
//                          (friction in every direction)             [m/s]
//   force on A at P:  f_A = -F_c u_t / sqrt(|u_t|^2 + v_s^2)          [N]
//   force on B at P:  f_B = -f_A
//   moments:  m_A = p_AoP_W x f_A,  m_B = p_BoP_W x f_B             [N.m]
//   potential energy 0, dissipated power
//   D = -f_A . u = F_c |u_t|^2 / sqrt(|u_t|^2 + v_s^2) >= 0          [W]
//
// |f_A| < F_c always, F_c |u_t| / v_s for |u_t| << v_s (a linear damper of
// F_c / v_s [N.s/m]) and F_c (1 - v_s^2 / (2 |u_t|^2)) for |u_t| >> v_s.
// Both forces act at P, so they have one line of action: no net moment
// about any point, and the power into the bodies is exactly -D.
// Q (B.p, fixed in B) enters the diagnostics only: length = |p_PQ| and its
// rate (the interface's), tension = f_A . e_PQ (0 when P = Q).
//
// F_c [N] must be finite and >= 0, v_s [m/s] finite and > 0; a_B finite,
// and zero or of length >= minimumGuideAxisNorm (ParameterError
// otherwise).
// Non-finite inputs throw InputError. No output is ever NaN.
#ifndef CONNECTORS_COULOMBFRICTION_COULOMBFRICTION_HPP
#define CONNECTORS_COULOMBFRICTION_COULOMBFRICTION_HPP

#include "common/Kinematics.hpp"

namespace connectors {

//- A non-zero B.axis shorter than this has no direction: refused [-]
inline constexpr double minimumGuideAxisNorm = 1e-12;

struct CoulombFrictionParameters {
    //- Contact point P on A, A's frame, from A's reference point [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Reference point Q on B, B's frame, from B's reference point; used
    //  by the diagnostics length, lengthRate and tension only [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Sliding direction (the guide) in B's frame, any length >=
    //  minimumGuideAxisNorm (normalised); zero: friction in every
    //  direction [-]
    Vector3 axis_B = Vector3::Zero();
    //- Coulomb (sliding) friction force F_c [N]
    double frictionForce = 0.0;
    //- Regularisation velocity v_s [m/s]
    double regularisationVelocity = 1e-3;
};

//- The law's result and its sliding diagnostics (the FMU's extra outputs)
struct CoulombFrictionResult {
    ConnectorResult loads;
    //- Sliding velocity a . u along the axis (|u| without an axis) [m/s]
    double slidingVelocity = 0.0;
    //- Friction force on A along the axis, f_A . a (|f_A| without an
    //  axis) [N]
    double friction = 0.0;
};

class CoulombFriction final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit CoulombFriction(const CoulombFrictionParameters& parameters);

    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    //- The loads and the sliding diagnostics
    CoulombFrictionResult evaluateSliding(const BodyKinematics& A,
                                          const BodyKinematics& B) const;

    const CoulombFrictionParameters& parameters() const { return parameters_; }

private:
    CoulombFrictionParameters parameters_;
    //- Unit guide direction in B's frame, zero for every direction [-]
    Vector3 a_B_;
};

} // namespace connectors

#endif

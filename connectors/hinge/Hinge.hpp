// Hinge (revolute joint) between body A and body B as a penalty force
// element, with an optional power take-off (PTO) about the hinge axis.
//
// Parameters in each body's frame: hinge points P (on A) and Q (on B), unit
// hinge axes a_A, a_B and reference directions e_A, e_B perpendicular to
// them (for the angle). In the global frame (subscript W dropped):
//
//   d = Q - P, gap = |d|, M = (P + Q)/2 the midpoint           [m]
//   v_M = velocity of B's material point at M minus A's         [m/s]
//   force on A at M:  f_A = k_t d + c_t v_M,  on B at M: -f_A   [N]
//   u = a_B x a_A, misalignment theta = atan2(|u|, a_A . a_B)  [rad]
//   w = w_B - w_A, w_perp = w - (w . a_A) a_A                  [rad/s]
//   aligning moment on B: M_B = k_r theta n - c_r w_perp,
//     n = u / |u| (n = e_A if the axes are opposite), on A: -M_B [N.m]
//   hinge angle phi: angle from e_A to e_B about a_A, unwrapped  [rad]
//   angleRate = w . a_A                                        [rad/s]
//   ptoTorque tau = k_p (phi - phi0) + c_p angleRate           [N.m]
//     moment on B: -tau a_A, on A: +tau a_A
//   ptoPower = tau angleRate (absorbed from the bodies)        [W]
//   potentialEnergy = k_t gap^2/2 + k_r theta^2/2 + k_p (phi - phi0)^2/2
//   dissipatedPower = c_t |v_M|^2 + c_r |w_perp|^2 + c_p angleRate^2 >= 0
//
// Every load vanishes when the constraint holds (d = 0, a_A = a_B, the
// bodies moving as one rigid hinge) at any angle, unless the PTO acts.
// Static constraint errors: gap = |load| / k_t, theta = |moment| / k_r.
// See connectors/hinge/README.md for the limits and the stability of the
// penalty in an explicit coupling.
#ifndef CONNECTORS_HINGE_HINGE_HPP
#define CONNECTORS_HINGE_HINGE_HPP

#include "common/Kinematics.hpp"

namespace connectors {

struct HingeParameters {
    //- Hinge point P on A, A's frame, from A's reference point [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Hinge point Q on B, B's frame, from B's reference point [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Hinge axis in A's frame, any non-zero length (normalised) [-]
    Vector3 axis_A = Vector3::UnitZ();
    //- Hinge axis in B's frame, any non-zero length (normalised) [-]
    Vector3 axis_B = Vector3::UnitZ();
    //- Angle reference direction in A's frame; its component along the
    //  axis is removed; zero: derived from the axis (see deriveReference)
    Vector3 ref_A = Vector3::Zero();
    //- The same in B's frame [-]
    Vector3 ref_B = Vector3::Zero();
    //- Translational penalty stiffness k_t [N/m]
    double stiffness = 0.0;
    //- Translational penalty damping c_t [N.s/m]
    double damping = 0.0;
    //- Rotational (alignment) penalty stiffness k_r [N.m/rad]
    double rotationalStiffness = 0.0;
    //- Rotational (alignment) penalty damping c_r [N.m.s/rad]
    double rotationalDamping = 0.0;
    //- PTO rotary stiffness about the axis k_p [N.m/rad]
    double ptoStiffness = 0.0;
    //- PTO rotary damping about the axis c_p [N.m.s/rad]
    double ptoDamping = 0.0;
    //- PTO rest angle phi0 [rad]
    double ptoRestAngle = 0.0;
};

//- Loads and diagnostics of the hinge
struct HingeResult {
    //- Loads on A and B; length = gap, lengthRate = d(gap)/dt, tension =
    //  the force along P->Q, potentialEnergy and dissipatedPower as above
    ConnectorResult loads;
    //- Unwrapped relative angle of B about the axis, from e_A to e_B [rad]
    double angle = 0.0;
    //- Relative angular velocity about A's axis [rad/s]
    double angleRate = 0.0;
    //- Distance between the hinge points [m]
    double gap = 0.0;
    //- Angle between the two hinge axes, in [0, pi] [rad]
    double misalignment = 0.0;
    //- PTO torque, positive when it resists a positive angle [N.m]
    double ptoTorque = 0.0;
    //- Power absorbed by the PTO from the bodies, tau angleRate [W]
    double ptoPower = 0.0;
};

//- Below this |a_A x a_B| with a_A . a_B < 0 the axes count as opposite
//  and the aligning moment turns about e_A [-]
inline constexpr double oppositeAxesTolerance = 1e-8;

//- The angle congruent to `raw` (mod 2 pi) nearest to `previous` [rad]
double unwrapAngle(double raw, double previous);

//- Unit vector perpendicular to the unit `axis`: the body-frame unit
//  vector (x, then y, then z) least aligned with the axis, with its axial
//  component removed
Vector3 deriveReference(const Vector3& axis);

class Hinge final : public ConnectorLaw {
public:
    //- Validates the parameters (ParameterError, or ConnectorError for a
    //  zero axis or a reference parallel to its axis), normalises the axes
    //  and builds the reference directions
    explicit Hinge(const HingeParameters& parameters);

    //- Loads and diagnostics; the angle is unwrapped against
    //  previousAngle (the angle of the previous evaluation) [rad]
    HingeResult evaluate(const BodyKinematics& A, const BodyKinematics& B,
                         double previousAngle) const;

    //- The loads with the angle taken in (-pi, pi]
    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    const HingeParameters& parameters() const { return parameters_; }

    //- Unit axes and unit reference directions, body frames [-]
    const Vector3& axisA() const { return axis_A_; }
    const Vector3& axisB() const { return axis_B_; }
    const Vector3& referenceA() const { return ref_A_; }
    const Vector3& referenceB() const { return ref_B_; }

private:
    HingeParameters parameters_;
    Vector3 axis_A_, axis_B_, ref_A_, ref_B_;
};

} // namespace connectors

#endif

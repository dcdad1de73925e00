#include "hinge/Hinge.hpp"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"

namespace connectors {

namespace {

const char* const lawName = "hinge";

//- An axis shorter than this counts as zero [-]
constexpr double minimumAxisNorm = 1e-12;
//- A reference direction within this sine of its axis counts as parallel
constexpr double minimumReferenceSine = 1e-6;

Vector3 unitAxis(const char* name, const Vector3& axis)
{
    requireFinite(lawName, name, axis, "1");
    const double norm = axis.norm();
    if (!(norm >= minimumAxisNorm)) {
        throw ParameterError(
            Refusal::noDirection, name,
            std::string(lawName) + ": parameter " + name + " = "
                + formatVector(axis)
                + " has no direction (allowed: a finite vector "
                  "of length >= 1e-12, normalised by the law)");
    }
    return axis / norm;
}

Vector3 unitReference(const char* name, const char* axisName,
                      const Vector3& reference, const Vector3& unitAxis)
{
    requireFinite(lawName, name, reference, "1");
    if (reference == Vector3::Zero()) {
        return deriveReference(unitAxis);
    }
    const Vector3 perpendicular
        = reference - reference.dot(unitAxis) * unitAxis;
    const double norm = perpendicular.norm();
    if (!(norm >= minimumReferenceSine * reference.norm())) {
        throw ParameterError(Refusal::inconsistent, name,
                             std::string(lawName) + ": parameter " + name
                                 + " = " + formatVector(reference)
                                 + " is parallel to " + axisName
                                 + " (allowed: a direction off the axis, or "
                                   "(0, 0, 0) to derive one)");
    }
    return perpendicular / norm;
}

} // namespace

double unwrapAngle(double raw, double previous)
{
    return previous + std::remainder(raw - previous, 2.0 * EIGEN_PI);
}

Vector3 deriveReference(const Vector3& axis)
{
    int least = 0;
    for (int i = 1; i < 3; ++i) {
        if (std::abs(axis[i]) < std::abs(axis[least])) {
            least = i;
        }
    }
    const Vector3 unit = Vector3::Unit(least);
    return (unit - unit.dot(axis) * axis).normalized();
}

Hinge::Hinge(const HingeParameters& parameters) : parameters_(parameters)
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    axis_A_ = unitAxis("A.axis", parameters.axis_A);
    axis_B_ = unitAxis("B.axis", parameters.axis_B);
    ref_A_ = unitReference("A.ref", "A.axis", parameters.ref_A, axis_A_);
    ref_B_ = unitReference("B.ref", "B.axis", parameters.ref_B, axis_B_);
    requireNonNegative(lawName, "stiffness", parameters.stiffness, "N/m");
    requireNonNegative(lawName, "damping", parameters.damping, "N.s/m");
    requireNonNegative(lawName, "rotationalStiffness",
                       parameters.rotationalStiffness, "N.m/rad");
    requireNonNegative(lawName, "rotationalDamping",
                       parameters.rotationalDamping, "N.m.s/rad");
    requireNonNegative(lawName, "ptoStiffness", parameters.ptoStiffness,
                       "N.m/rad");
    requireNonNegative(lawName, "ptoDamping", parameters.ptoDamping,
                       "N.m.s/rad");
    if (!std::isfinite(parameters.ptoRestAngle)) {
        throw ParameterError(Refusal::notFinite, lawName, "ptoRestAngle",
                             parameters.ptoRestAngle, "rad", "finite");
    }
}

HingeResult Hinge::evaluate(const BodyKinematics& A, const BodyKinematics& B,
                            double previousAngle) const
{
    requireFiniteInputs(lawName, A, B);
    const HingeParameters& p = parameters_;
    const AxialGeometry g = axialGeometry(A, B, p.p_AoP_A, p.p_BoQ_B);

    HingeResult h;
    ConnectorResult& r = h.loads;

    // Translation: a vector spring-damper, defined at any gap (no direction
    // needed), acting on both bodies at the midpoint M of P and Q so that
    // the pair carries no net moment. The damper acts on the relative
    // velocity of the material points of A and B at M (frame-indifferent).
    const Vector3 half_W = 0.5 * g.p_PQ_W;
    const Vector3 p_AoM_W = g.p_AoP_W + half_W;
    const Vector3 p_BoM_W = g.p_BoQ_W - half_W;
    const Vector3 v_M_W = (B.v_WKo_W + B.w_WK_W.cross(p_BoM_W))
        - (A.v_WKo_W + A.w_WK_W.cross(p_AoM_W));
    const Vector3 f_A_W = p.stiffness * g.p_PQ_W + p.damping * v_M_W;
    r.A.f_W = f_A_W;
    r.A.m_Ko_W = p_AoM_W.cross(f_A_W);
    r.B.f_W = -f_A_W;
    r.B.m_Ko_W = p_BoM_W.cross(-f_A_W);

    // Alignment: turns a_B towards a_A about n = (a_B x a_A)/|a_B x a_A|.
    const Vector3 a_A_W = A.R_WK * axis_A_;
    const Vector3 a_B_W = B.R_WK * axis_B_;
    const Vector3 e_A_W = A.R_WK * ref_A_;
    const Vector3 e_B_W = B.R_WK * ref_B_;
    const Vector3 u_W = a_B_W.cross(a_A_W);
    const double sine = u_W.norm();
    const double cosine = a_A_W.dot(a_B_W);
    const double theta = std::atan2(sine, cosine);
    Vector3 align_B_W;
    if (cosine < 0.0 && sine < oppositeAxesTolerance) {
        // Opposite axes: every direction perpendicular to a_A turns a_B
        // back; the body-fixed e_A is the documented choice.
        align_B_W = p.rotationalStiffness * theta * e_A_W;
    } else {
        // theta / sin(theta) -> 1 as the axes align
        const double ratio = sine > 0.0 ? theta / sine : 1.0;
        align_B_W = p.rotationalStiffness * ratio * u_W;
    }
    const Vector3 w_AB_W = B.w_WK_W - A.w_WK_W;
    const double angleRate = w_AB_W.dot(a_A_W);
    const Vector3 wPerp_W = w_AB_W - angleRate * a_A_W;

    // Angle from e_A to e_B about a_A; the axial part of e_B drops out.
    const double raw
        = std::atan2(a_A_W.dot(e_A_W.cross(e_B_W)), e_A_W.dot(e_B_W));
    const double angle = unwrapAngle(raw, previousAngle);
    const double twist = angle - p.ptoRestAngle;
    const double tau = p.ptoStiffness * twist + p.ptoDamping * angleRate;

    const Vector3 m_B_W
        = align_B_W - p.rotationalDamping * wPerp_W - tau * a_A_W;
    r.B.m_Ko_W += m_B_W;
    r.A.m_Ko_W -= m_B_W;

    r.length = g.length;
    r.lengthRate = g.lengthRate;
    r.tension = g.axisDefined ? f_A_W.dot(g.e_W) : 0.0;
    r.potentialEnergy = 0.5 * p.stiffness * g.p_PQ_W.squaredNorm()
        + 0.5 * p.rotationalStiffness * theta * theta
        + 0.5 * p.ptoStiffness * twist * twist;
    r.dissipatedPower = p.damping * v_M_W.squaredNorm()
        + p.rotationalDamping * wPerp_W.squaredNorm()
        + p.ptoDamping * angleRate * angleRate;

    h.angle = angle;
    h.angleRate = angleRate;
    h.gap = g.length;
    h.misalignment = theta;
    h.ptoTorque = tau;
    h.ptoPower = tau * angleRate;
    return h;
}

ConnectorResult Hinge::evaluate(const BodyKinematics& A,
                                const BodyKinematics& B) const
{
    return evaluate(A, B, 0.0).loads;
}

} // namespace connectors

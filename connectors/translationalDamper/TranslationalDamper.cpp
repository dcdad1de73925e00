#include "translationalDamper/TranslationalDamper.hpp"

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"

#include <Eigen/Geometry>

namespace connectors {

namespace {
const char* const lawName = "translationalDamper";
}

TranslationalDamper::TranslationalDamper(
    const TranslationalDamperParameters& parameters)
    : parameters_(parameters)
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    requireNonNegative(lawName, "damping", parameters.damping, "N.s/m");
}

ConnectorResult TranslationalDamper::evaluate(const BodyKinematics& A,
                                              const BodyKinematics& B) const
{
    requireFiniteInputs(lawName, A, B);

    const double c = parameters_.damping;
    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);

    // B's material point at P: its arm from B's reference point, velocity
    const Vector3 p_BoP_W = A.p_WKo_W + g.p_AoP_W - B.p_WKo_W;
    const Vector3 v_rel_W = B.v_WKo_W + B.w_WK_W.cross(p_BoP_W)
        - (A.v_WKo_W + A.w_WK_W.cross(g.p_AoP_W));
    const Vector3 f_A_W = c * v_rel_W;

    ConnectorResult result;
    result.A.f_W = f_A_W;
    result.A.m_Ko_W = g.p_AoP_W.cross(f_A_W);
    result.B.f_W = -f_A_W;
    result.B.m_Ko_W = p_BoP_W.cross(-f_A_W);
    result.length = g.length;
    result.lengthRate = g.lengthRate; // 0 when the axis is undefined
    result.tension = f_A_W.dot(g.e_W); // e = 0 when the axis is undefined
    result.potentialEnergy = 0.0;
    result.dissipatedPower = c * v_rel_W.squaredNorm();
    return result;
}

} // namespace connectors

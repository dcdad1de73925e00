#include "rotationalDamper/RotationalDamper.hpp"

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"

namespace connectors {

namespace {
const char* const lawName = "rotationalDamper";
}

RotationalDamper::RotationalDamper(const RotationalDamperParameters& parameters)
    : parameters_(parameters)
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    requireNonNegative(lawName, "damping", parameters.damping, "N.m.s/rad");
}

ConnectorResult RotationalDamper::evaluate(const BodyKinematics& A,
                                           const BodyKinematics& B) const
{
    requireFiniteInputs(lawName, A, B);

    const double c = parameters_.damping;
    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);
    const Vector3 w_rel_W = B.w_WK_W - A.w_WK_W;

    ConnectorResult result;
    result.A.m_Ko_W = c * w_rel_W;
    result.B.m_Ko_W = -result.A.m_Ko_W;
    result.length = g.length;
    result.lengthRate = g.lengthRate; // 0 when the axis is undefined
    result.tension = 0.0;
    result.potentialEnergy = 0.0;
    result.dissipatedPower = c * w_rel_W.squaredNorm();
    return result;
}

} // namespace connectors

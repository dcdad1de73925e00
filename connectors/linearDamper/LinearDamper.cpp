#include "linearDamper/LinearDamper.hpp"

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"

namespace connectors {

namespace {
const char* const lawName = "linearDamper";
}

LinearDamper::LinearDamper(const LinearDamperParameters& parameters)
    : parameters_(parameters)
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    requireNonNegative(lawName, "damping", parameters.damping, "N.s/m");
}

ConnectorResult LinearDamper::evaluate(const BodyKinematics& A,
                                       const BodyKinematics& B) const
{
    requireFiniteInputs(lawName, A, B);

    const double c = parameters_.damping;
    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);

    ConnectorResult result;
    const double tension = c * g.lengthRate; // 0 when the axis is undefined
    applyPointForce(g, tension * g.e_W, result);
    result.length = g.length;
    result.lengthRate = g.lengthRate;
    result.tension = tension;
    result.potentialEnergy = 0.0;
    result.dissipatedPower = c * g.lengthRate * g.lengthRate;
    return result;
}

} // namespace connectors

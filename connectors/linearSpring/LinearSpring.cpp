#include "linearSpring/LinearSpring.hpp"

#include <string>

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"

namespace connectors {

namespace {
const char* const lawName = "linearSpring";
}

LinearSpring::LinearSpring(const LinearSpringParameters& parameters)
    : parameters_(parameters)
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    requireNonNegative(lawName, "stiffness", parameters.stiffness, "N/m");
    requireNonNegative(lawName, "restLength", parameters.restLength, "m");
    requireNonNegative(lawName, "damping", parameters.damping, "N.s/m");
}

ConnectorResult LinearSpring::evaluate(const BodyKinematics& A,
                                       const BodyKinematics& B) const
{
    requireFiniteInputs(lawName, A, B);

    const double k = parameters_.stiffness;
    const double L0 = parameters_.restLength;
    const double c = parameters_.damping;
    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);

    if (!g.axisDefined && k * L0 > 0.0) {
        throw UndefinedStateError(
            std::string(lawName) + ": length " + formatValue(g.length)
            + " m is below " + formatValue(minimumAxisLength)
            + " m with restLength = " + formatValue(L0)
            + " m > 0: the spring force direction is undefined");
    }

    // Elastic part: k (L - L0) e, or the vector k p_PQ when L0 = 0, which
    // is the same force and stays defined at zero length.
    const Vector3 elastic = L0 == 0.0 ? Vector3(k * g.p_PQ_W)
                                      : Vector3(k * (g.length - L0) * g.e_W);
    const double dampingTension = c * g.lengthRate;

    ConnectorResult result;
    applyPointForce(g, elastic + dampingTension * g.e_W, result);
    result.length = g.length;
    result.lengthRate = g.lengthRate;
    result.tension = k * (g.length - L0) + dampingTension;
    result.potentialEnergy = 0.5 * k * (g.length - L0) * (g.length - L0);
    result.dissipatedPower = c * g.lengthRate * g.lengthRate;
    return result;
}

} // namespace connectors

#include "common/ReferenceOrientation.hpp"

#include <cmath>
#include <string>

#include "common/ConnectorError.hpp"

namespace connectors {

void requireReferenceOrientation(const char* law, const Matrix3& R_BA0)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double q = R_BA0(i, j);
            if (!std::isfinite(q)) {
                throw ParameterError(Refusal::notFinite, law,
                                     "referenceOrientation["
                                         + std::to_string(i + 1) + ","
                                         + std::to_string(j + 1) + "]",
                                     q, "1", "finite");
            }
        }
    }
    const double offNorm = R_BA0.norm() - std::sqrt(3.0);
    if (std::abs(offNorm) > rotationNormTolerance) {
        throw ParameterError(
            Refusal::outOfRange, "referenceOrientation",
            std::string(law)
                + ": parameter referenceOrientation is not a rotation tensor: "
                  "|referenceOrientation| - sqrt(3) = "
                + formatValue(offNorm)
                + " (allowed: within 3.2e-08 of 0, as OpenFOAM reads it)");
    }
}

} // namespace connectors

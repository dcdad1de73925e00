#include "sphericalAngularSpring/SphericalAngularSpring.hpp"

#include <Eigen/Geometry>

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"
#include "common/ReferenceOrientation.hpp"

namespace connectors {

namespace {
const char* const lawName = "sphericalAngularSpring";
}

SphericalAngularSpring::SphericalAngularSpring(
    const SphericalAngularSpringParameters& parameters)
    : parameters_(parameters)
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    requireReferenceOrientation(lawName, parameters.R_BA0);
    requireNonNegative(lawName, "stiffness", parameters.stiffness, "N.m/rad");
    requireNonNegative(lawName, "damping", parameters.damping, "N.m.s/rad");
}

ConnectorResult SphericalAngularSpring::evaluate(const BodyKinematics& A,
                                                 const BodyKinematics& B) const
{
    requireFiniteInputs(lawName, A, B);

    const Matrix3 R_BA = B.R_WK.transpose() * A.R_WK;
    const Matrix3& Q0 = parameters_.R_BA0;
    const double k = parameters_.stiffness;
    const double c = parameters_.damping;

    // OpenFOAM's restrain(), in B's frame: each axis of the reference
    // frame, the next axis and where A has turned it, less its part along
    // the first
    Vector3 m_B = Vector3::Zero();
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const Vector3 axis = Q0 * Vector3::Unit(i);
        const Vector3 refDir = Q0 * Vector3::Unit(j);
        Vector3 newDir = R_BA * Vector3::Unit(j);
        newDir -= axis.dot(newDir) * axis;
        m_B += -k * refDir.cross(newDir);
    }
    const Vector3 w_rel_B = B.R_WK.transpose() * (A.w_WK_W - B.w_WK_W);
    m_B += -c * w_rel_B;

    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);
    ConnectorResult result;
    result.A.m_Ko_W = B.R_WK * m_B;
    result.B.m_Ko_W = -result.A.m_Ko_W;
    result.length = g.length;
    result.lengthRate = g.lengthRate;
    result.tension = 0.0;
    // k (1 - cos theta): |R - Q0|^2 = |Q0^T R - I|^2 = 6 - 2 tr(Q0^T R),
    // never negative and without the cancellation of the trace near 0
    result.potentialEnergy = 0.25 * k * (R_BA - Q0).squaredNorm();
    result.dissipatedPower = c * w_rel_B.squaredNorm();
    return result;
}

} // namespace connectors

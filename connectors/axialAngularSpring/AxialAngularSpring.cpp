#include "axialAngularSpring/AxialAngularSpring.hpp"

#include "common/AxialAngle.hpp"
#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"
#include "common/ReferenceOrientation.hpp"

namespace connectors {

namespace {

const char* const lawName = "axialAngularSpring";

//- OpenFOAM's VSMALL (doubleScalar)
constexpr double vSmall = 1e-300;

} // namespace

AxialAngularSpring::AxialAngularSpring(
    const AxialAngularSpringParameters& parameters)
    : parameters_(parameters)
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    n_B_ = unitAxis(lawName, parameters.axis_B);
    requireReferenceOrientation(lawName, parameters.R_BA0);
    requireNonNegative(lawName, "stiffness", parameters.stiffness, "N.m/rad");
    requireNonNegative(lawName, "damping", parameters.damping, "N.m.s/rad");
}

ConnectorResult AxialAngularSpring::evaluate(const BodyKinematics& A,
                                             const BodyKinematics& B) const
{
    requireFiniteInputs(lawName, A, B);

    const Vector3& n = n_B_;
    const Matrix3 R_BA = B.R_WK.transpose() * A.R_WK;
    const AxialAngle angle = axialAngle(n, parameters_.R_BA0, R_BA);
    const double theta = angle.magnitude;

    // The axis with the sense of the turn from u to w
    Vector3 a = angle.sense * n;
    const double magA = a.norm();
    a = magA > vSmall ? Vector3(a / magA) : Vector3(Vector3::Zero());

    const Vector3 w_rel_B = B.R_WK.transpose() * (A.w_WK_W - B.w_WK_W);
    const double turnRate = w_rel_B.dot(a);
    const double k = parameters_.stiffness;
    const double c = parameters_.damping;

    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);
    ConnectorResult result;
    result.A.m_Ko_W = B.R_WK * (-(k * theta + c * turnRate) * a);
    result.B.m_Ko_W = -result.A.m_Ko_W;
    result.length = g.length;
    result.lengthRate = g.lengthRate;
    result.tension = 0.0;
    result.potentialEnergy = 0.5 * k * theta * theta;
    result.dissipatedPower = c * turnRate * turnRate;
    return result;
}

} // namespace connectors

#include "axialAngularSpring/AxialAngularSpring.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"
#include "common/ReferenceOrientation.hpp"

namespace connectors {

namespace {

const char* const lawName = "axialAngularSpring";

//- Below this length [-] an axis has no direction
constexpr double minimumAxisNorm = 1e-12;

//- OpenFOAM's VSMALL and SMALL (doubleScalar)
constexpr double vSmall = 1e-300;
constexpr double small = 1e-15;

//- OpenFOAM's rotationTensor(n1, n2) (transform.H, v1912 and v2312): the
//  rotation in the plane of n1 and n2 that turns n1 onto n2; the mirror
//  I + 2 n1 n2 where they are opposite, I where they coincide
Matrix3 rotationTensor(const Vector3& n1, const Vector3& n2)
{
    const double s = n1.dot(n2);
    const Vector3 n3 = n1.cross(n2);
    const double magSqrN3 = n3.squaredNorm();
    if (magSqrN3 > small) {
        return s * Matrix3::Identity()
            + (1 - s) * n3 * n3.transpose() / magSqrN3
            + (n2 * n1.transpose() - n1 * n2.transpose());
    }
    if (s < 0) {
        return Matrix3::Identity() + 2 * n1 * n2.transpose();
    }
    return Matrix3::Identity();
}

//- v less its part along the unit vector n, normalised as OpenFOAM does
Vector3 normalAndUnit(const Vector3& v, const Vector3& n)
{
    const Vector3 w = v - n.dot(v) * n;
    return w / (w.norm() + vSmall);
}

} // namespace

AxialAngularSpring::AxialAngularSpring(
    const AxialAngularSpringParameters& parameters)
    : parameters_(parameters)
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    requireFinite(lawName, "B.axis", parameters.axis_B, "1");
    const double norm = parameters.axis_B.norm();
    if (norm < minimumAxisNorm) {
        throw ParameterError(Refusal::noDirection, "B.axis",
                             std::string(lawName) + ": parameter B.axis = "
                                 + formatVector(parameters.axis_B)
                                 + " has no direction (allowed: a finite "
                                   "vector of length >= 1e-12, normalised by "
                                   "the law)");
    }
    n_B_ = parameters.axis_B / norm;
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
    const Matrix3& Q0 = parameters_.R_BA0;
    const Matrix3 T = rotationTensor(Vector3::UnitX(), n);

    Vector3 d = T * Vector3::UnitY();
    Vector3 u = Q0 * d;
    Vector3 w = R_BA * d;
    if (std::abs(u.dot(n)) > 0.95 || std::abs(w.dot(n)) > 0.95) {
        // Directions near the axis: OpenFOAM's other reference
        d = T * Vector3::UnitZ();
        u = Q0 * d;
        w = R_BA * d;
    }
    u = normalAndUnit(u, n);
    w = normalAndUnit(w, n);
    const double theta = std::abs(std::acos(std::clamp(u.dot(w), -1.0, 1.0)));

    // The axis with the sense of the turn from u to w
    Vector3 a = u.cross(w).dot(n) * n;
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

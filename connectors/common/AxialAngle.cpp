#include "common/AxialAngle.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "common/ConnectorError.hpp"

namespace connectors {

namespace {

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

AxialAngle axialAngle(const Vector3& n_B, const Matrix3& R_BA0,
                      const Matrix3& R_BA)
{
    const Vector3& n = n_B;
    const Matrix3& Q0 = R_BA0;
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
    AxialAngle angle;
    angle.magnitude = std::abs(std::acos(std::clamp(u.dot(w), -1.0, 1.0)));
    angle.sense = u.cross(w).dot(n);
    return angle;
}

Vector3 unitAxis(const char* law, const Vector3& axis_B)
{
    requireFinite(law, "B.axis", axis_B, "1");
    const double norm = axis_B.norm();
    if (norm < minimumAxisNorm) {
        throw ParameterError(Refusal::noDirection, "B.axis",
                             std::string(law) + ": parameter B.axis = "
                                 + formatVector(axis_B)
                                 + " has no direction (allowed: a finite "
                                   "vector of length >= 1e-12, normalised by "
                                   "the law)");
    }
    return axis_B / norm;
}

} // namespace connectors

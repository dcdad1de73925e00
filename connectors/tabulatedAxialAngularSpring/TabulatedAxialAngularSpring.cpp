#include "tabulatedAxialAngularSpring/TabulatedAxialAngularSpring.hpp"

#include <string>

#include "common/AxialAngle.hpp"
#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"
#include "common/ReferenceOrientation.hpp"

namespace connectors {

namespace {

const char* const lawName = "tabulatedAxialAngularSpring";

//- OpenFOAM's constant::mathematical::pi and radToDeg
constexpr double pi = 3.14159265358979323846;

double radToDeg(double rad)
{
    return rad * 180.0 / pi;
}

MomentTable momentTable(const TabulatedAxialAngularSpringParameters& p)
{
    return MomentTable(lawName, p.angle, p.moment,
                       p.angleInDegrees ? "deg" : "rad", p.outOfBounds);
}

} // namespace

TabulatedAxialAngularSpring::TabulatedAxialAngularSpring(
    const TabulatedAxialAngularSpringParameters& parameters)
    : parameters_(parameters), n_B_(unitAxis(lawName, parameters.axis_B)),
      table_(momentTable(parameters)), integralToZero_(table_.integral(0.0))
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    requireReferenceOrientation(lawName, parameters.R_BA0);
    requireNonNegative(lawName, "damping", parameters.damping, "N.m.s/rad");
}

ConnectorResult
TabulatedAxialAngularSpring::evaluate(const BodyKinematics& A,
                                      const BodyKinematics& B) const
{
    requireFiniteInputs(lawName, A, B);

    const Vector3& n = n_B_;
    const Matrix3 R_BA = B.R_WK.transpose() * A.R_WK;
    const AxialAngle angle = axialAngle(n, parameters_.R_BA0, R_BA);
    const double theta = angle.magnitude * (angle.sense >= 0 ? 1.0 : -1.0);
    const bool degrees = parameters_.angleInDegrees;
    const double x = degrees ? radToDeg(theta) : theta;
    if (parameters_.outOfBounds == OutOfBounds::error && table_.outside(x)) {
        throw UndefinedStateError(
            std::string(lawName) + ": angle " + formatValue(x)
            + (degrees ? " deg" : " rad") + " outside the table's ["
            + formatValue(table_.first()) + ", " + formatValue(table_.last())
            + ") with outOfBounds error (0)");
    }
    const double M = table_.value(x);

    const Vector3 w_rel_B = B.R_WK.transpose() * (A.w_WK_W - B.w_WK_W);
    const double turnRate = w_rel_B.dot(n);
    const double c = parameters_.damping;

    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);
    ConnectorResult result;
    result.A.m_Ko_W = B.R_WK * ((M - c * turnRate) * n);
    result.B.m_Ko_W = -result.A.m_Ko_W;
    result.length = g.length;
    result.lengthRate = g.lengthRate;
    result.tension = 0.0;
    result.potentialEnergy = -(table_.integral(x) - integralToZero_)
        * (degrees ? pi / 180.0 : 1.0);
    result.dissipatedPower = c * turnRate * turnRate;
    return result;
}

} // namespace connectors

#include "coulombFriction/CoulombFriction.hpp"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"

namespace connectors {

namespace {
const char* const lawName = "coulombFriction";
}

CoulombFriction::CoulombFriction(const CoulombFrictionParameters& parameters)
    : parameters_(parameters), a_B_(Vector3::Zero())
{
    requireFiniteAttachments(lawName, parameters.p_AoP_A, parameters.p_BoQ_B);
    requireFinite(lawName, "B.axis", parameters.axis_B, "1");
    const double norm = parameters.axis_B.norm();
    if (norm > 0.0 && norm < minimumGuideAxisNorm) {
        throw ParameterError(Refusal::noDirection, "B.axis",
                             std::string(lawName) + ": parameter B.axis = "
                                 + formatVector(parameters.axis_B)
                                 + " has no direction (allowed: (0, 0, 0) for "
                                   "friction in every direction, or a finite "
                                   "vector of length >= 1e-12, normalised by "
                                   "the law)");
    }
    if (norm > 0.0) {
        a_B_ = parameters.axis_B / norm;
    }
    requireNonNegative(lawName, "frictionForce", parameters.frictionForce, "N");
    requirePositive(lawName, "regularisationVelocity",
                    parameters.regularisationVelocity, "m/s");
}

ConnectorResult CoulombFriction::evaluate(const BodyKinematics& A,
                                          const BodyKinematics& B) const
{
    return evaluateSliding(A, B).loads;
}

CoulombFrictionResult
CoulombFriction::evaluateSliding(const BodyKinematics& A,
                                 const BodyKinematics& B) const
{
    requireFiniteInputs(lawName, A, B);

    const double Fc = parameters_.frictionForce;
    const double vs = parameters_.regularisationVelocity;
    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);

    // P from B's reference point, and u = v_WP - v_WB(P): the velocity of
    // B's material point at P is v_WQ + w_B x p_QP = v_WQ - w_B x p_PQ.
    const Vector3 p_BoP_W = g.p_BoQ_W - g.p_PQ_W;
    const Vector3 u_W = B.w_WK_W.cross(g.p_PQ_W) - g.v_PQ_W;

    const bool guided = a_B_.squaredNorm() > 0.0;
    const Vector3 a_W = B.R_WK * a_B_;
    const double ua = a_W.dot(u_W);
    const Vector3 ut_W = guided ? Vector3(ua * a_W) : u_W;
    const double speed = guided ? std::abs(ua) : u_W.stableNorm();
    // hypot: no overflow of |u_t|^2; the quotient is below 1 in magnitude
    const double root = std::hypot(speed, vs);
    const Vector3 f_A = -Fc / root * ut_W;

    CoulombFrictionResult r;
    r.loads.A.f_W = f_A;
    r.loads.A.m_Ko_W = g.p_AoP_W.cross(f_A);
    r.loads.B.f_W = -f_A;
    r.loads.B.m_Ko_W = p_BoP_W.cross(-f_A);
    r.loads.length = g.length;
    r.loads.lengthRate = g.lengthRate;
    r.loads.tension = f_A.dot(g.e_W); // e = 0 when P = Q
    r.loads.potentialEnergy = 0.0;
    r.loads.dissipatedPower = Fc * speed * (speed / root);
    r.slidingVelocity = guided ? ua : speed;
    r.friction = guided ? f_A.dot(a_W) : f_A.norm();
    return r;
}

} // namespace connectors

// Helpers for the hinge law tests: parameters and a body B placed so that
// the hinge constraint holds exactly with respect to a given body A.
#ifndef TESTS_CONNECTORS_HINGETESTSUPPORT_HPP
#define TESTS_CONNECTORS_HINGETESTSUPPORT_HPP

#include "LawTestSupport.hpp"
#include "hinge/Hinge.hpp"

namespace lawTest {

using connectors::Hinge;
using connectors::HingeParameters;
using connectors::HingeResult;

//- Skew hinge with every coefficient non-zero
inline HingeParameters genericHinge()
{
    HingeParameters p;
    p.p_AoP_A = Vector3(0.3, -0.1, 0.2);
    p.p_BoQ_B = Vector3(-0.2, 0.4, 0.1);
    p.axis_A = Vector3(1, 2, 2); // |a| = 3: normalised by the law
    p.axis_B = Vector3(0, -1, 1);
    p.ref_A = Vector3(1, 0, 0);
    p.ref_B = Vector3(1, 1, 1);
    p.stiffness = 800.0;
    p.damping = 12.0;
    p.rotationalStiffness = 300.0;
    p.rotationalDamping = 4.0;
    p.ptoStiffness = 25.0;
    p.ptoDamping = 7.0;
    p.ptoRestAngle = 0.4;
    return p;
}

//- Body B on which the hinge holds exactly: Q on P, a_B on a_A, e_B at
//  `angle` from e_A about the axis, B turning relative to A about the axis
//  at `angleRate` [rad/s] with Q moving with P
inline BodyKinematics hingedBody(const Hinge& hinge, const BodyKinematics& A,
                                 double angle, double angleRate)
{
    const Vector3 a_W = A.R_WK * hinge.axisA();
    const Vector3 e_W = rotation(angle, a_W) * (A.R_WK * hinge.referenceA());
    Matrix3 target, body;
    target << e_W, a_W.cross(e_W), a_W;
    body << hinge.referenceB(), hinge.axisB().cross(hinge.referenceB()),
        hinge.axisB();
    BodyKinematics B;
    B.R_WK = target * body.transpose();
    const Vector3 lever_A_W = A.R_WK * hinge.parameters().p_AoP_A;
    const Vector3 lever_B_W = B.R_WK * hinge.parameters().p_BoQ_B;
    const Vector3 p_WP = A.p_WKo_W + lever_A_W;
    B.p_WKo_W = p_WP - lever_B_W;
    B.w_WK_W = A.w_WK_W + angleRate * a_W;
    const Vector3 v_WP = A.v_WKo_W + A.w_WK_W.cross(lever_A_W);
    B.v_WKo_W = v_WP - B.w_WK_W.cross(lever_B_W);
    return B;
}

//- The body moved rigidly for a time dt at its velocities (exact rotation)
inline BodyKinematics advanced(const BodyKinematics& k, double dt)
{
    BodyKinematics m = k;
    m.p_WKo_W += dt * k.v_WKo_W;
    const double w = k.w_WK_W.norm();
    if (w > 0.0) {
        m.R_WK = rotation(w * dt, k.w_WK_W) * k.R_WK;
    }
    return m;
}

} // namespace lawTest

#endif

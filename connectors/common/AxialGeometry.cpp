#include "common/AxialGeometry.hpp"

#include <Eigen/Geometry>

namespace connectors {

AxialGeometry axialGeometry(const BodyKinematics& A, const BodyKinematics& B,
                            const Vector3& p_AoP_A, const Vector3& p_BoQ_B)
{
    AxialGeometry g;
    g.p_AoP_W = A.R_WK * p_AoP_A;
    g.p_BoQ_W = B.R_WK * p_BoQ_B;
    g.p_PQ_W = (B.p_WKo_W + g.p_BoQ_W) - (A.p_WKo_W + g.p_AoP_W);

    const Vector3 v_WP_W = A.v_WKo_W + A.w_WK_W.cross(g.p_AoP_W);
    const Vector3 v_WQ_W = B.v_WKo_W + B.w_WK_W.cross(g.p_BoQ_W);
    g.v_PQ_W = v_WQ_W - v_WP_W;

    g.length = g.p_PQ_W.norm();
    g.axisDefined = g.length >= minimumAxisLength;
    if (g.axisDefined) {
        g.e_W = g.p_PQ_W / g.length;
        g.lengthRate = g.e_W.dot(g.v_PQ_W);
    }
    return g;
}

void applyPointForce(const AxialGeometry& geometry, const Vector3& f_A_W,
                     ConnectorResult& result)
{
    result.A.f_W = f_A_W;
    result.A.m_Ko_W = geometry.p_AoP_W.cross(f_A_W);
    result.B.f_W = -f_A_W;
    result.B.m_Ko_W = geometry.p_BoQ_W.cross(-f_A_W);
}

} // namespace connectors

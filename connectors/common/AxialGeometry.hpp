// Geometry of a two-point connector: attachment point P fixed in A, Q fixed
// in B, and the axis from P to Q. Shared by the spring and the damper.
#ifndef CONNECTORS_COMMON_AXIALGEOMETRY_HPP
#define CONNECTORS_COMMON_AXIALGEOMETRY_HPP

#include "common/Kinematics.hpp"

namespace connectors {

//- Below this length [m] the axis direction P->Q is treated as undefined
inline constexpr double minimumAxisLength = 1e-12;

struct AxialGeometry {
    //- Lever arm of P from Ao, global frame: R_WA p_AoP_A [m]
    Vector3 p_AoP_W;
    //- Lever arm of Q from Bo, global frame: R_WB p_BoQ_B [m]
    Vector3 p_BoQ_W;
    //- Position of Q from P, global frame [m]
    Vector3 p_PQ_W;
    //- Velocity of Q relative to P (v_WQ - v_WP), global frame [m/s]
    Vector3 v_PQ_W;
    //- Length |p_PQ_W| [m]
    double length = 0.0;
    //- True when length >= minimumAxisLength; only then are e and
    //  lengthRate defined
    bool axisDefined = false;
    //- Unit vector from P to Q, global frame (zero if !axisDefined) [-]
    Vector3 e_W = Vector3::Zero();
    //- d(length)/dt = e . v_PQ (zero if !axisDefined) [m/s]
    double lengthRate = 0.0;
};

//- Attachment points p_AoP_A (in A's frame) and p_BoQ_B (in B's frame) [m]
AxialGeometry axialGeometry(const BodyKinematics& A, const BodyKinematics& B,
                            const Vector3& p_AoP_A, const Vector3& p_BoQ_B);

//- Loads on A and B for a force f_A_W on A at P and its reaction -f_A_W on
//  B at Q, with the moments about each body's reference point
void applyPointForce(const AxialGeometry& geometry, const Vector3& f_A_W,
                     ConnectorResult& result);

} // namespace connectors

#endif

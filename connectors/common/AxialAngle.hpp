// The turn of body A relative to body B about an axis fixed in B, measured
// as OpenFOAM's sixDoF linearAxialAngularSpring and
// tabulatedAxialAngularSpring restraints measure it (v1912, v2312). Shared
// by the axialAngularSpring and tabulatedAxialAngularSpring laws.
//
// In B's frame, with n the unit axis, R = R_WB^T R_WA A's orientation
// relative to B and Q0 its reference orientation:
//
//   d = T e_y, T = rotationTensor(e_x, n) (OpenFOAM's: turns e_x onto n);
//     d = T e_z where |n . Q0 d| > 0.95 or |n . R d| > 0.95
//   u = Q0 d, w = R d, each less its part along n, normalised
//   magnitude = |acos(min(max(u . w, -1), 1))|                     [rad]
//   sense = (u x w) . n                                            [-]
//
// OpenFOAM takes acos of min(u . w, 1) only (NaN just beyond -1 by
// round-off); here u . w is also held above -1.
#ifndef CONNECTORS_COMMON_AXIALANGLE_HPP
#define CONNECTORS_COMMON_AXIALANGLE_HPP

#include "common/Kinematics.hpp"

namespace connectors {

struct AxialAngle {
    //- The angle of A from its reference about n, without sign, in [0, pi]
    //  [rad]
    double magnitude = 0.0;
    //- (u x w) . n: its sign is the sense of the turn about n [-]
    double sense = 0.0;
};

//- The angle of A relative to B about the unit axis n_B (B's frame), A's
//  orientation relative to B being R_BA and its reference R_BA0
AxialAngle axialAngle(const Vector3& n_B, const Matrix3& R_BA0,
                      const Matrix3& R_BA);

//- The parameter B.axis normalised; throws ParameterError (notFinite,
//  noDirection) naming it unless it is finite and of length >= 1e-12
Vector3 unitAxis(const char* law, const Vector3& axis_B);

} // namespace connectors

#endif

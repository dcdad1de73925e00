// The referenceOrientation of OpenFOAM's angular springs (sixDoF
// linearAxialAngularSpring, tabulatedAxialAngularSpring and
// sphericalAngularSpring): A's orientation relative to B where the spring
// holds no moment, checked as OpenFOAM reads it. Shared by
// axialAngularSpring, tabulatedAxialAngularSpring and sphericalAngularSpring.
#ifndef CONNECTORS_COMMON_REFERENCEORIENTATION_HPP
#define CONNECTORS_COMMON_REFERENCEORIENTATION_HPP

#include "common/Kinematics.hpp"

namespace connectors {

//- OpenFOAM's ROOTSMALL (doubleScalar): how far the norm of a rotation
//  tensor may be from sqrt(3) [-]
inline constexpr double rotationNormTolerance = 3.1622776601683794e-8;

//- Throws ParameterError naming "referenceOrientation[i,j]" for the first
//  non-finite component (row by row), or "referenceOrientation" where its
//  Frobenius norm is further than rotationNormTolerance from sqrt(3): what
//  OpenFOAM's read() refuses as "not a rotation tensor"
void requireReferenceOrientation(const char* law, const Matrix3& R_BA0);

} // namespace connectors

#endif

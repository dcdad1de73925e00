// The scalar parameters of mooringLine.fmu (the first section's and the
// line's own): name, unit, description, start value and where the model
// keeps each one's value reference. Declared once, here.
#ifndef FMU_MOORINGLINE_SCALARPARAMETERS_HPP
#define FMU_MOORINGLINE_SCALARPARAMETERS_HPP

#include <cstddef>

#include "VariableTable.hpp"

namespace mooringLineFmu {

//- The value references of the scalar parameters, one member each
struct ScalarBlocks {
    fmuExport::Block length, EA, axialDamping, massPerLength, diameter,
        waterDensity, gravity, normalDrag, tangentialDrag, normalAddedMass,
        tangentialAddedMass, seabedContact, seabedStiffness, seabedDamping,
        segments, relativeTolerance, absoluteTolerance, hermiteEnds, integrator,
        maxStep, freeSurface, waterLevel, seabedFriction, frictionVelocity,
        endInertia, axialFrictionRatio, staticFrictionScale;
};

struct Scalar {
    const char* name;
    const char* unit;
    const char* description;
    double start;
    //- Where the model keeps its value reference
    fmuExport::Block ScalarBlocks::*block;
};

// Model-scale start values: a 1.5 m line of 0.5 kg/m between two points
// 1 m apart, in two-body mode
inline constexpr Scalar scalars[] = {
    {"unstretchedLength", "m",
     "unstretched length L, > 0, at least the ends' distance at the start "
     "over 1.3",
     1.5, &ScalarBlocks::length},
    {"EA", "N", "axial stiffness, > 0", 1e4, &ScalarBlocks::EA},
    {"axialDamping", "N.s", "axial damping BA (tension per strain rate), >= 0",
     10.0, &ScalarBlocks::axialDamping},
    {"massPerLength", "kg/m", "dry mass per unstretched length, > 0", 0.5,
     &ScalarBlocks::massPerLength},
    {"diameter", "m",
     "volume-equivalent diameter (buoyancy, drag, added mass, seabed contact), "
     ">= 0 (> 0 with seabedContact = 1)",
     0.01, &ScalarBlocks::diameter},
    {"waterDensity", "kg/m3", "water density, >= 0", 1025.0,
     &ScalarBlocks::waterDensity},
    {"gravity", "m/s2", "gravitational acceleration (along -z), >= 0", 9.81,
     &ScalarBlocks::gravity},
    {"normalDrag", "1", "transverse drag coefficient Cdn, >= 0", 1.2,
     &ScalarBlocks::normalDrag},
    {"tangentialDrag", "1", "tangential drag coefficient Cdt, >= 0", 0.05,
     &ScalarBlocks::tangentialDrag},
    {"normalAddedMass", "1", "transverse added-mass coefficient Can, >= 0", 1.0,
     &ScalarBlocks::normalAddedMass},
    {"tangentialAddedMass", "1", "tangential added-mass coefficient Cat, >= 0",
     0.0, &ScalarBlocks::tangentialAddedMass},
    {"seabedContact", "1",
     "1: B.p is an anchor on the seabed (the horizontal plane through it); 0: no "
     "seabed",
     0.0, &ScalarBlocks::seabedContact},
    {"seabedStiffness", "Pa/m",
     "seabed penalty stiffness per contact area, >= 0 (> 0 with "
     "seabedContact = 1)",
     3e6, &ScalarBlocks::seabedStiffness},
    {"seabedDamping", "Pa.s/m", "seabed penalty damping per contact area, >= 0",
     3e5, &ScalarBlocks::seabedDamping},
    {"segments", "1", "number of segments N, an integer from 2 to 1000", 20.0,
     &ScalarBlocks::segments},
    {"relativeTolerance", "1", "CVODE relative tolerance, > 0 (integrator 1)",
     1e-6, &ScalarBlocks::relativeTolerance},
    {"absoluteTolerance", "1",
     "CVODE absolute tolerance (m, m/s), > 0 (integrator 1)", 1e-6,
     &ScalarBlocks::absoluteTolerance},
    {"hermiteEnds", "1",
     "1: within a step the ends follow the cubic Hermite curve through the positions "
     "and velocities at both ends; 0: straight lines between the positions",
     1.0, &ScalarBlocks::hermiteEnds},
    {"integrator", "1",
     "0: implicit trapezoidal rule (default); 1: SUNDIALS CVODE (BDF)", 0.0,
     &ScalarBlocks::integrator},
    {"maxStep", "s",
     "longest trapezoidal substep, >= 0 (0: one step per coupling step)", 0.0,
     &ScalarBlocks::maxStep},
    {"freeSurface", "1",
     "1: no buoyancy, drag or added mass above waterLevel (a node's submerged "
     "fraction ramps from 1 to 0 over one segment length around it); 0: the "
     "whole line is submerged",
     0.0, &ScalarBlocks::freeSurface},
    {"waterLevel", "m",
     "height (global z) of the still water surface: the free surface "
     "(freeSurface = 1) and the top of the current profile",
     0.0, &ScalarBlocks::waterLevel},
    {"seabedFriction", "1",
     "seabed Coulomb friction coefficient across the line (along it "
     "axialFrictionRatio times it), >= 0 (0: none)",
     0.0, &ScalarBlocks::seabedFriction},
    {"frictionVelocity", "m/s",
     "speed below which the seabed friction is regularised (proportional to "
     "the speed), > 0",
     0.01, &ScalarBlocks::frictionVelocity},
    {"endInertia", "1",
     "1: the loads include the inertia of the end nodes' half segments "
     "(mass and added mass times the attachment point's acceleration, "
     "explicit in the coupling); 0 (default): not",
     0.0, &ScalarBlocks::endInertia},
    {"axialFrictionRatio", "1",
     "seabed friction along the line over that across it (seabedFriction), "
     ">= 0 (1: isotropic)",
     1.0, &ScalarBlocks::axialFrictionRatio},
    {"staticFrictionScale", "1",
     "static over kinetic seabed friction, >= 1: below frictionVelocity the "
     "friction reaches this times the kinetic one, falling to it at twice "
     "that speed (1: none)",
     1.0, &ScalarBlocks::staticFrictionScale},
};
inline constexpr std::size_t scalarCount = sizeof scalars / sizeof scalars[0];

} // namespace mooringLineFmu

#endif

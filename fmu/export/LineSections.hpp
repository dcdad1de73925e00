// The variables of a line of sections that the line FMUs share
// (catenary.fmu, mooringLine.fmu): the tension at each section's ends and
// the joints' positions, and the section of each shape point. Sections are
// numbered from B.p (1) towards A.p; FMI 2.0 fixes the variables in
// modelDescription.xml, so they exist for every section the FMU can take,
// and an absent section's or joint's are 0.
#ifndef FMU_EXPORT_LINESECTIONS_HPP
#define FMU_EXPORT_LINESECTIONS_HPP

#include <string>
#include <vector>

#include "common/Kinematics.hpp"

namespace fmuExport {
namespace lineSections {

//- Name, unit and description of one scalar variable
struct Variable {
    std::string name, unit, description;
};

//- section.lowerTension[1..maxSections], section.upperTension[...],
//  joint.x[1..maxSections - 1], joint.y[...], joint.z[...]; `where` says
//  where along the section the tension is taken (e.g. " in its segment")
std::vector<Variable> endVariables(int maxSections, const std::string& where);

//- Their values for the sections present (per section from B.p: the
//  tension at its lower and upper end [N]; the joints' positions, global
//  frame [m]); 0 for the absent ones
std::vector<double> endValues(int maxSections,
                              const std::vector<double>& lowerTension,
                              const std::vector<double>& upperTension,
                              const std::vector<connectors::Vector3>& joints);

//- shape.section[1..shapePoints]
std::vector<Variable> shapeVariables(int shapePoints);

//- For `shapePoints` points from A.p to B.p at equal steps of unstretched
//  arc (the shape outputs), the number of the section each lies in: the
//  sections' unstretched lengths from B.p (empty: one section). A point
//  at a joint lies in the section above it (towards A.p).
std::vector<double> shapeSections(const std::vector<double>& lengths,
                                  int shapePoints);

} // namespace lineSections
} // namespace fmuExport

#endif

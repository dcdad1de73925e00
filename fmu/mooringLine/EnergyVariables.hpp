// The energy outputs of mooringLine.fmu: the line's kinetic energy, the
// work done on it (by its ends, the water and the added mass) and the
// energy it dissipated (drag, seabed, axial damping) since
// fmi2ExitInitializationMode, whole and per section, so that
//
//   fairleadWork + anchorWork + waterWork + addedMassWork
//     = change of (kineticEnergy + potentialEnergy) + dissipatedEnergy
//
// (connectors/mooringLine/LineEnergy.hpp). Declared once, here.
#ifndef FMU_MOORINGLINE_ENERGYVARIABLES_HPP
#define FMU_MOORINGLINE_ENERGYVARIABLES_HPP

#include <vector>

#include "LineSections.hpp"
#include "mooringLine/MooringLine.hpp"

namespace mooringLineFmu {

namespace energyVariables {

//- The outputs, in order: kineticEnergy, fairleadWork, anchorWork,
//  waterWork, addedMassWork, dissipatedEnergy, dragDissipated,
//  seabedDissipated, axialDissipated, then per section k = 1..sections
//  section.kineticEnergy[k], section.dragDissipated[k],
//  section.seabedDissipated[k], section.axialDissipated[k]
std::vector<fmuExport::lineSections::Variable> outputs(int sections);

//- Their values: the kinetic energy of the law's output `m`, the account
//  `total` summed since the start (0 for absent sections)
std::vector<double> values(const connectors::MooringLineOutput& m,
                           const connectors::LineEnergy& total, int sections);

} // namespace energyVariables

} // namespace mooringLineFmu

#endif

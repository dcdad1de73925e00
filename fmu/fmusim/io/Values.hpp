// An FMU's variables read back as text for CSV output.
#ifndef FMUSIM_IO_VALUES_HPP
#define FMUSIM_IO_VALUES_HPP

#include "fmuImport/fmuImport.hpp"

#include <string>
#include <vector>

namespace fmusim {

// The FMU's outputs, in the order of its modelDescription.xml.
std::vector<const fmuImport::Variable*> outputsOf(const fmuImport::Fmu& fmu);

// The current values of the variables, as text for CSV output, with one
// get call per type. A NaN or infinite Real throws fmuImport::Error
// (nonFiniteMessage).
std::vector<std::string>
readValues(fmuImport::Instance& instance,
           const std::vector<const fmuImport::Variable*>& variables);

// "FMU 'x.fmu', instance 'x': output 'y' is nan at t = 0.5, expected a
// finite number"; what: "output 'y'" or "variable 'y'".
std::string nonFiniteMessage(const fmuImport::Instance& instance,
                             const std::string& what, double value,
                             double time);

} // namespace fmusim

#endif

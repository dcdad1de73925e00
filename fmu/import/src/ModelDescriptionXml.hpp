// Reading modelDescription.xml with pugixml.
#ifndef FMUIMPORT_MODELDESCRIPTIONXML_HPP
#define FMUIMPORT_MODELDESCRIPTIONXML_HPP

#include "fmuImport/fmuImport.hpp"

#include <string>

namespace fmuImport {

// Parses xml, the bytes of modelDescription.xml of the FMU fmuPath (named
// in errors). Requires fmiVersion "2.0" and a <CoSimulation> element; the
// model identifier is the one of <CoSimulation>, a C identifier.
ModelDescription readModelDescription(const std::string& xml,
                                      const std::string& fmuPath);

} // namespace fmuImport

#endif

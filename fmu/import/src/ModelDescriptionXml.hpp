// Reading modelDescription.xml with pugixml.
#ifndef FMUIMPORT_MODELDESCRIPTIONXML_HPP
#define FMUIMPORT_MODELDESCRIPTIONXML_HPP

#include "fmuImport/fmuImport.hpp"

#include <filesystem>
#include <string>

namespace fmuImport {

// Parses the description at xmlFile of the FMU fmuPath (named in errors).
// Requires fmiVersion "2.0" and a <CoSimulation> element; the model
// identifier is the one of <CoSimulation>.
ModelDescription readModelDescription(const std::filesystem::path& xmlFile, const std::string& fmuPath);

}  // namespace fmuImport

#endif

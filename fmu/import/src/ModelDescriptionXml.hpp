// Reading modelDescription.xml with pugixml.
#ifndef FMUIMPORT_MODELDESCRIPTIONXML_HPP
#define FMUIMPORT_MODELDESCRIPTIONXML_HPP

#include "fmuImport/fmuImport.hpp"

#include <pugixml.hpp>

#include <string>

namespace fmuImport {

// Parses xml, the bytes of modelDescription.xml of the FMU fmuPath (named
// in errors). Requires fmiVersion "2.0" or "3.0" and a <CoSimulation>
// element; the model identifier is the one of <CoSimulation>, a C
// identifier.
ModelDescription readModelDescription(const std::string& xml,
                                      const std::string& fmuPath);

// The binary of a description's FMU in the archive (and in the unpack
// directory): binaries/linux64/<id>.so (FMI 2.0) or
// binaries/x86_64-linux/<id>.so (FMI 3.0).
std::string binaryEntry(const ModelDescription& md);

// FMI 3.0 (ModelDescriptionXml3.cpp): root is <fmiModelDescription>.
ModelDescription readFmi3Description(const pugi::xml_node& root,
                                     const std::string& fmuPath);

// What both versions' readers share
namespace xml {
std::string fmuName(const std::string& fmuPath); // "FMU 'x.fmu'"
bool isCIdentifier(const std::string& s);
Causality parseCausality(const std::string& s, const std::string& where);
Variability parseVariability(const std::string& s, const std::string& where);
// A start value as a number (Boolean: true/false/1/0 as 1/0)
double parseNumber(const std::string& s, Type type, const std::string& where);
// <CoSimulation>'s modelIdentifier, checked
std::string modelIdentifier(const pugi::xml_node& cs, const std::string& fmu);
// <CoSimulation>'s modelIdentifier and capabilities; state: "FMUstate"
// (FMI 2.0's canGetAndSetFMUstate) or "FMUState" (FMI 3.0's)
void readCoSimulation(const pugi::xml_node& cs, const std::string& fmu,
                      const std::string& state, ModelDescription& md);
void readDefaultExperiment(const pugi::xml_node& root, ModelDescription& md);
} // namespace xml

} // namespace fmuImport

#endif

// modelDescription.xml (FMI 2.0 and 3.0), terminalsAndIcons.xml,
// documentation/index.html and the GUID, all generated from a model's
// identity and variable table.
#ifndef FMU_EXPORT_MODELDESCRIPTION_HPP
#define FMU_EXPORT_MODELDESCRIPTION_HPP

#include <string>

#include "Model.hpp"

namespace fmuExport {

//- Log categories the FMUs declare and accept in fmi2SetDebugLogging
inline constexpr const char* logCategoryError = "logStatusError";
inline constexpr const char* logCategoryCalls = "logCalls";
//- A refused parameter, "<name> <code>: <message>" (debug logging)
inline constexpr const char* logCategoryRefusal = "refusedParameter";

//- "{xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx}": a 128-bit hash of the identity
//  and the full variable table, the same on every build and platform
std::string modelGuid(const Model& model);

//- The FMI 2.0 co-simulation modelDescription.xml; throws std::logic_error
//  for a unit that has no SI definition here
std::string modelDescriptionXml(const Model& model);

//- The FMI 3.0 co-simulation modelDescription.xml: the same variables,
//  vectors and matrices as arrays (Fmi3Variables.hpp), instantiationToken
//  the GUID
std::string modelDescription3Xml(const Model& model);

//- terminalsAndIcons/terminalsAndIcons.xml of the FMI 3.0 FMU: a terminal
//  per body ("A", "B") with every variable whose name starts with "A." or
//  "B."
std::string terminalsAndIconsXml(const Model& model);

//- documentation/index.html: law and variable table
std::string documentationHtml(const Model& model);

//- Shortest "%.*g" text that reads back as exactly `value`
std::string formatDouble(double value);

} // namespace fmuExport

#endif

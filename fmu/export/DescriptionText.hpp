// Text shared by the FMI 2.0 and FMI 3.0 descriptions: attribute values as
// modelDescription.xml spells them, units as SI base-unit exponents, XML
// escaping.
#ifndef FMU_EXPORT_DESCRIPTIONTEXT_HPP
#define FMU_EXPORT_DESCRIPTIONTEXT_HPP

#include <string>

#include "VariableTable.hpp"

namespace fmuExport {

const char* causalityName(Causality c);
const char* variabilityName(Variability v);
//- "" for Initial::none
const char* initialName(Initial i);

//- BaseUnit attributes of a unit (m="1" s="-1"); throws std::logic_error
//  for a unit that has no SI definition here
const char* baseUnitOf(const std::string& unit);

//- Text with & < > " escaped for an XML attribute or element
std::string escape(const std::string& text);

//- The UnitDefinitions (every unit of a Real variable, SI base units) and
//  LogCategories elements of modelDescription.xml; `prefix` "fmi2" or
//  "fmi3" names the functions logged in category logCalls
std::string unitsAndLogCategoriesXml(const VariableTable& table,
                                     const char* prefix);

} // namespace fmuExport

#endif

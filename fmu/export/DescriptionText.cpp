#include "DescriptionText.hpp"

#include <cstddef>
#include <set>
#include <sstream>
#include <stdexcept>

#include "ModelDescription.hpp"

namespace fmuExport {

namespace {

struct UnitDefinition {
    const char* name;
    const char* baseUnit; // BaseUnit attributes: SI exponents
};

//- SI base-unit exponents of every unit a variable may use
constexpr UnitDefinition unitDefinitions[] = {
    {"1", ""},
    {"m", "m=\"1\""},
    {"m2", "m=\"2\""},
    {"m3", "m=\"3\""},
    {"kg", "kg=\"1\""},
    {"rad", "rad=\"1\""},
    {"s", "s=\"1\""},
    {"m/s", "m=\"1\" s=\"-1\""},
    {"rad/s", "s=\"-1\" rad=\"1\""},
    {"N", "kg=\"1\" m=\"1\" s=\"-2\""},
    {"N.m", "kg=\"1\" m=\"2\" s=\"-2\""},
    {"N.m/rad", "kg=\"1\" m=\"2\" s=\"-2\" rad=\"-1\""},
    {"N.m.s/rad", "kg=\"1\" m=\"2\" s=\"-1\" rad=\"-1\""},
    {"J", "kg=\"1\" m=\"2\" s=\"-2\""},
    {"W", "kg=\"1\" m=\"2\" s=\"-3\""},
    {"N/m", "kg=\"1\" s=\"-2\""},
    {"N.s/m", "kg=\"1\" s=\"-1\""},
    {"kg.m2", "kg=\"1\" m=\"2\""},
    {"N.s", "kg=\"1\" m=\"1\" s=\"-1\""},
    {"kg/m", "kg=\"1\" m=\"-1\""},
    {"kg/m3", "kg=\"1\" m=\"-3\""},
    {"m/s2", "m=\"1\" s=\"-2\""},
    {"Pa/m", "kg=\"1\" m=\"-2\" s=\"-2\""},
    {"Pa.s/m", "kg=\"1\" m=\"-2\" s=\"-1\""},
};

//- The name of an enumerator, from the names in the enumeration's order;
//  "" for a value outside it
template <class Enum, std::size_t N>
const char* nameOf(Enum value, const char* const (&names)[N])
{
    const auto i = static_cast<std::size_t>(value);
    return i < N ? names[i] : "";
}

} // namespace

const char* causalityName(Causality c)
{
    return nameOf(c, {"parameter", "input", "output", "local"});
}

const char* variabilityName(Variability v)
{
    return nameOf(v, {"constant", "fixed", "continuous"});
}

const char* initialName(Initial i)
{
    return nameOf(i, {"", "exact", "calculated"});
}

const char* baseUnitOf(const std::string& unit)
{
    for (const UnitDefinition& d : unitDefinitions) {
        if (unit == d.name) {
            return d.baseUnit;
        }
    }
    throw std::logic_error("unit \"" + unit
                           + "\" has no SI base-unit definition");
}

std::string escape(const std::string& text)
{
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string unitsAndLogCategoriesXml(const VariableTable& table,
                                     const char* prefix)
{
    std::set<std::string> used;
    for (const ScalarVariable& v : table.variables()) {
        if (v.type == Type::Real) {
            used.insert(v.unit);
        }
    }
    std::ostringstream x;
    x << "  <UnitDefinitions>\n";
    for (const std::string& unit : used) {
        const std::string base = baseUnitOf(unit);
        x << "    <Unit name=\"" << escape(unit) << "\"><BaseUnit " << base
          << (base.empty() ? "" : " ") << "/></Unit>\n";
    }
    x << "  </UnitDefinitions>\n";

    x << "  <LogCategories>\n"
      << "    <Category name=\"" << logCategoryError
      << "\" description=\"Errors: the function, the variable and its "
         "value\"/>\n"
      << "    <Category name=\"" << logCategoryCalls
      << "\" description=\"Every " << prefix
      << " call (when debug logging is on)\"/>\n"
      << "    <Category name=\"" << logCategoryRefusal
      << "\" description=\"A refused parameter, before its error: its name, "
         "a space, the refusal's code, a colon and the error's text (when "
         "debug logging is on)\"/>\n"
      << "  </LogCategories>\n";
    return x.str();
}

} // namespace fmuExport

#include "ModelDescriptionXml.hpp"

#include <pugixml.hpp>

#include <cctype>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <set>

namespace fmuImport {

namespace xml {

std::string fmuName(const std::string& fmuPath)
{
    return "FMU '" + fmuPath + "'";
}

bool isCIdentifier(const std::string& s)
{
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0])))
        return false;
    for (const char c : s) {
        if (!(c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')
              || (c >= '0' && c <= '9')))
            return false;
    }
    return true;
}

// The enumerator named s, from the names in the enumeration's order; Error
// naming the attribute and the value otherwise
template <class Enum, std::size_t N>
Enum parseName(const char* const (&names)[N], const std::string& s,
               const char* attribute, const std::string& where)
{
    for (std::size_t i = 0; i < N; ++i)
        if (s == names[i])
            return static_cast<Enum>(i);
    throw Error(where + ": unknown " + attribute + " '" + s + "'");
}

Causality parseCausality(const std::string& s, const std::string& where)
{
    static const char* const names[]
        = {"parameter",   "calculatedParameter", "input", "output", "local",
           "independent", "structuralParameter"};
    return s.empty() ? Causality::local
                     : parseName<Causality>(names, s, "causality", where);
}

Variability parseVariability(const std::string& s, const std::string& where)
{
    static const char* const names[]
        = {"constant", "fixed", "tunable", "discrete", "continuous"};
    return s.empty() ? Variability::continuous
                     : parseName<Variability>(names, s, "variability", where);
}

double parseNumber(const std::string& s, Type type, const std::string& where)
{
    if (type == Type::Boolean) {
        if (s == "true" || s == "1")
            return 1;
        if (s == "false" || s == "0")
            return 0;
        throw Error(where + ": Boolean start value '" + s
                    + "' is neither true nor false");
    }
    const char* begin = s.c_str();
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || *end != '\0')
        throw Error(where + ": start value '" + s + "' is not a number");
    return value;
}

} // namespace xml

namespace {

using namespace xml;

Variable readVariable(const pugi::xml_node& node, const std::string& fmu)
{
    Variable v;
    v.name = node.attribute("name").as_string();
    const std::string where = fmu + ": variable '" + v.name + "'";
    if (v.name.empty())
        throw Error(fmu + ": a ScalarVariable has no name");
    if (!node.attribute("valueReference"))
        throw Error(where + " has no valueReference");
    v.valueReference = node.attribute("valueReference").as_uint();
    v.causality
        = parseCausality(node.attribute("causality").as_string(), where);
    v.variability
        = parseVariability(node.attribute("variability").as_string(), where);
    v.description = node.attribute("description").as_string();

    const pugi::xml_node typeNode = node.first_child();
    const std::string typeName = typeNode.name();
    if (typeName == "Real")
        v.type = Type::Real;
    else if (typeName == "Integer")
        v.type = Type::Integer;
    else if (typeName == "Boolean")
        v.type = Type::Boolean;
    else if (typeName == "String")
        v.type = Type::String;
    else if (typeName == "Enumeration")
        v.type = Type::Enumeration;
    else
        throw Error(
            where
            + " has no type element (Real, Integer, Boolean, String or Enumeration)");

    v.unit = typeNode.attribute("unit").as_string();
    if (const pugi::xml_attribute start = typeNode.attribute("start")) {
        v.hasStart = true;
        v.startString = start.as_string();
        if (v.type != Type::String)
            v.start = parseNumber(v.startString, v.type, where);
    }
    return v;
}

} // namespace

namespace xml {

std::string modelIdentifier(const pugi::xml_node& cs, const std::string& fmu)
{
    const std::string id = cs.attribute("modelIdentifier").as_string();
    if (id.empty())
        throw Error(fmu + ": <CoSimulation> has no modelIdentifier");
    // It names the binary, binaries/<platform>/<modelIdentifier>.so: a C
    // identifier, as FMI requires, cannot reach outside that folder.
    if (!isCIdentifier(id))
        throw Error(
            fmu + ": modelIdentifier '" + id
            + "' is not a C identifier (letters, digits and '_', not starting with a digit)");
    return id;
}

void readCoSimulation(const pugi::xml_node& cs, const std::string& fmu,
                      const std::string& state, ModelDescription& md)
{
    md.modelIdentifier = modelIdentifier(cs, fmu);
    md.canHandleVariableCommunicationStepSize
        = cs.attribute("canHandleVariableCommunicationStepSize").as_bool();
    md.canGetAndSetFMUstate
        = cs.attribute(("canGetAndSet" + state).c_str()).as_bool();
    md.canSerializeFMUstate
        = cs.attribute(("canSerialize" + state).c_str()).as_bool();
    md.providesDirectionalDerivative
        = cs.attribute("providesDirectionalDerivative").as_bool();
    md.canBeInstantiatedOnlyOncePerProcess
        = cs.attribute("canBeInstantiatedOnlyOncePerProcess").as_bool();
}

void readDefaultExperiment(const pugi::xml_node& root, ModelDescription& md)
{
    if (const pugi::xml_node de = root.child("DefaultExperiment")) {
        md.hasDefaultExperiment = true;
        md.startTime = de.attribute("startTime").as_double(0);
        md.stopTime = de.attribute("stopTime").as_double(0);
        md.stepSize = de.attribute("stepSize").as_double(0);
    }
}

} // namespace xml

ModelDescription readModelDescription(const std::string& xml,
                                      const std::string& fmuPath)
{
    using namespace xml;
    const std::string fmu = fmuName(fmuPath);
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed
        = doc.load_buffer(xml.data(), xml.size());
    if (!parsed)
        throw Error(fmu + ": modelDescription.xml is not well-formed XML ("
                    + parsed.description() + " at byte "
                    + std::to_string(parsed.offset) + ")");
    const pugi::xml_node root = doc.child("fmiModelDescription");
    if (!root)
        throw Error(
            fmu
            + ": modelDescription.xml has no <fmiModelDescription> element");

    ModelDescription md;
    md.fmiVersion = root.attribute("fmiVersion").as_string();
    if (md.fmiVersion == "3.0")
        return readFmi3Description(root, fmuPath);
    if (md.fmiVersion != "2.0")
        throw Error(
            fmu + ": fmiVersion is '" + md.fmiVersion
            + "', only FMI 2.0 (\"2.0\") and FMI 3.0 (\"3.0\") are supported");
    md.modelName = root.attribute("modelName").as_string();
    md.guid = root.attribute("guid").as_string();
    md.description = root.attribute("description").as_string();
    md.generationTool = root.attribute("generationTool").as_string();

    const pugi::xml_node cs = root.child("CoSimulation");
    if (!cs)
        throw Error(
            fmu
            + ": modelDescription.xml has no <CoSimulation> element (model exchange is not supported)");
    readCoSimulation(cs, fmu, "FMUstate", md);

    readDefaultExperiment(root, md);

    std::set<std::string> names;
    for (const pugi::xml_node node :
         root.child("ModelVariables").children("ScalarVariable")) {
        Variable v = readVariable(node, fmu);
        if (!names.insert(v.name).second)
            throw Error(fmu + ": variable '" + v.name + "' is declared twice");
        md.variables.push_back(std::move(v));
    }
    return md;
}

std::string binaryEntry(const ModelDescription& md)
{
    return std::string(md.fmiMajorVersion == 3 ? "binaries/x86_64-linux/"
                                               : "binaries/linux64/")
        + md.modelIdentifier + ".so";
}

} // namespace fmuImport

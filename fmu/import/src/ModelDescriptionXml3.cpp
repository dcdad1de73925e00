// Reading an FMI 3.0 modelDescription.xml: the variables by element type,
// arrays (<Dimension>) shown as one Variable per element (fmuImport.hpp,
// Variable), and the refusals of what the importer cannot drive:
// model exchange or scheduled execution only, clocks.
#include "ModelDescriptionXml.hpp"

#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

namespace fmuImport {

namespace {

using namespace xml;

// The element types of FMI 3.0 and the importer's Type of each
const std::map<std::string, Type>& elementTypes()
{
    static const std::map<std::string, Type> types {
        {"Float32", Type::Real},    {"Float64", Type::Real},
        {"Int8", Type::Integer},    {"UInt8", Type::Integer},
        {"Int16", Type::Integer},   {"UInt16", Type::Integer},
        {"Int32", Type::Integer},   {"UInt32", Type::Integer},
        {"Int64", Type::Integer},   {"UInt64", Type::Integer},
        {"Boolean", Type::Boolean}, {"String", Type::String},
        {"Binary", Type::String},   {"Enumeration", Type::Enumeration}};
    return types;
}

// The most elements of all variables together
const std::size_t maxElements = 1000000;

// One variable as declared, before its elements are made
struct Declared {
    pugi::xml_node node;
    std::string name, typeName;
    unsigned int valueReference;
};

std::vector<std::string> splitBlanks(const std::string& text)
{
    std::istringstream in(text);
    std::vector<std::string> tokens;
    for (std::string token; in >> token;)
        tokens.push_back(token);
    return tokens;
}

// The start values of a declared variable: the attribute start (numbers,
// blank-separated) or, for String and Binary, the <Start value=".."/>
// children. Empty when none is given.
std::vector<std::string> startValues(const Declared& d)
{
    if (d.typeName == "String" || d.typeName == "Binary") {
        std::vector<std::string> values;
        for (const pugi::xml_node s : d.node.children("Start"))
            values.push_back(s.attribute("value").as_string());
        return values;
    }
    return splitBlanks(d.node.attribute("start").as_string());
}

// "A.r[2]", "A.R[1,3]" for the element at position k (row-major)
std::string elementName(const std::string& base,
                        const std::vector<std::size_t>& dimensions,
                        std::size_t k)
{
    std::vector<std::size_t> index(dimensions.size());
    for (std::size_t d = dimensions.size(); d-- > 0;) {
        index[d] = k % dimensions[d] + 1;
        k /= dimensions[d];
    }
    std::string name = base + "[";
    for (std::size_t d = 0; d < index.size(); ++d)
        name += (d ? "," : "") + std::to_string(index[d]);
    return name + "]";
}

} // namespace

ModelDescription readFmi3Description(const pugi::xml_node& root,
                                     const std::string& fmuPath)
{
    const std::string fmu = fmuName(fmuPath);
    ModelDescription md;
    md.fmiVersion = "3.0";
    md.fmiMajorVersion = 3;
    md.modelName = root.attribute("modelName").as_string();
    md.guid = root.attribute("instantiationToken").as_string();
    md.description = root.attribute("description").as_string();
    md.generationTool = root.attribute("generationTool").as_string();

    const pugi::xml_node cs = root.child("CoSimulation");
    if (!cs) {
        const bool me = root.child("ModelExchange");
        const bool se = root.child("ScheduledExecution");
        throw Error(
            fmu
            + ": modelDescription.xml (FMI 3.0) has no <CoSimulation> element: "
            + (me && se ? "model exchange and scheduled execution only"
                   : me ? "model exchange only"
                   : se ? "scheduled execution only"
                        : "no interface type")
            + ", and the importer runs co-simulation FMUs only");
    }
    readCoSimulation(cs, fmu, "FMUState", md);
    md.hasEventMode = cs.attribute("hasEventMode").as_bool();
    readDefaultExperiment(root, md);

    // Units of declared types (<Float64Type name=".." unit=".."/>)
    std::map<std::string, std::string> typeUnits;
    for (const pugi::xml_node t : root.child("TypeDefinitions").children())
        typeUnits[t.attribute("name").as_string()]
            = t.attribute("unit").as_string();

    std::vector<Declared> declared;
    std::map<unsigned int, std::size_t> byReference;
    for (const pugi::xml_node node : root.child("ModelVariables").children()) {
        if (node.type() != pugi::node_element)
            continue;
        Declared d {node, node.attribute("name").as_string(), node.name(), 0};
        if (d.name.empty())
            throw Error(fmu + ": a <" + d.typeName + "> variable has no name");
        const std::string where = fmu + ": variable '" + d.name + "'";
        if (d.typeName == "Clock")
            throw Error(
                where
                + " is a Clock: the importer cannot drive clocks (it runs "
                  "co-simulation without event mode)");
        if (!elementTypes().count(d.typeName))
            throw Error(where + " has the unknown type <" + d.typeName + ">");
        if (node.attribute("clocks"))
            throw Error(where + " is clocked (clocks=\""
                        + node.attribute("clocks").as_string()
                        + "\"): the importer cannot drive clocks (it runs "
                          "co-simulation without event mode)");
        if (!node.attribute("valueReference"))
            throw Error(where + " has no valueReference");
        d.valueReference = node.attribute("valueReference").as_uint();
        if (!byReference.emplace(d.valueReference, declared.size()).second)
            throw Error(where + " has valueReference "
                        + std::to_string(d.valueReference) + ", as variable '"
                        + declared[byReference[d.valueReference]].name
                        + "' has: FMI 3.0 value references are unique");
        declared.push_back(d);
    }

    // Value references of the elements after an array's first one: its own
    // plus the position where no declared variable has those, else above
    // every value reference of the FMU
    std::set<unsigned int> taken;
    for (const auto& entry : byReference)
        taken.insert(entry.first);
    unsigned int spare = taken.empty() ? 0 : *taken.rbegin() + 1;

    std::set<std::string> names;
    std::size_t elements = 0;
    for (const Declared& d : declared) {
        const std::string where = fmu + ": variable '" + d.name + "'";
        std::vector<std::size_t> dimensions;
        for (const pugi::xml_node dim : d.node.children("Dimension")) {
            if (dim.attribute("start")) {
                dimensions.push_back(dim.attribute("start").as_ullong());
                continue;
            }
            // A structural parameter's start value
            const unsigned int ref = dim.attribute("valueReference").as_uint();
            const auto found = byReference.find(ref);
            if (!dim.attribute("valueReference") || found == byReference.end())
                throw Error(where
                            + " has a <Dimension> with neither start nor the "
                              "valueReference of a structural parameter");
            const Declared& size = declared[found->second];
            dimensions.push_back(std::strtoull(
                size.node.attribute("start").as_string(), nullptr, 10));
        }
        // Every element is a Variable: a description of more elements than
        // a connector could use is refused before they are made
        std::size_t count = 1;
        for (const std::size_t n : dimensions) {
            if (n == 0)
                throw Error(where + " is an array without elements");
            if (n > maxElements / count)
                throw Error(where + " has more than "
                            + std::to_string(maxElements)
                            + " elements, more than the importer takes");
            count *= n;
        }
        elements += count;
        if (elements > maxElements)
            throw Error(where + ": the FMU's variables have more than "
                        + std::to_string(maxElements)
                        + " elements, more than the importer takes");

        Variable v;
        v.typeName = d.typeName;
        v.type = elementTypes().at(d.typeName);
        v.causality
            = parseCausality(d.node.attribute("causality").as_string(), where);
        const std::string variability
            = d.node.attribute("variability").as_string();
        // FMI 3.0: only Float32 and Float64 default to continuous
        v.variability = parseVariability(
            !variability.empty() || v.type == Type::Real ? variability
                                                         : "discrete",
            where);
        v.description = d.node.attribute("description").as_string();
        v.unit = d.node.attribute("unit").as_string();
        if (v.unit.empty() && d.node.attribute("declaredType"))
            v.unit = typeUnits[d.node.attribute("declaredType").as_string()];
        v.arrayValueReference = d.valueReference;

        const std::vector<std::string> starts = startValues(d);
        if (!starts.empty() && starts.size() != 1 && starts.size() != count)
            throw Error(where + " has " + std::to_string(starts.size())
                        + " start values, expected " + std::to_string(count)
                        + " (one per element)");

        // Its elements' value references: consecutive from its own, if free
        bool consecutive = true;
        for (std::size_t k = 1; k < count && consecutive; ++k)
            consecutive = !taken.count(d.valueReference + unsigned(k));
        for (std::size_t k = 0; k < count; ++k) {
            Variable e = v;
            if (!dimensions.empty()) {
                e.name = elementName(d.name, dimensions, k);
                e.arrayName = d.name;
                e.dimensions = dimensions;
                e.element = k;
            } else {
                e.name = d.name;
            }
            e.valueReference = k == 0 ? d.valueReference
                : consecutive         ? d.valueReference + unsigned(k)
                                      : spare++;
            taken.insert(e.valueReference);
            if (!starts.empty()) {
                e.hasStart = true;
                e.startString = starts[starts.size() == 1 ? 0 : k];
                if (e.type != Type::String)
                    e.start = parseNumber(e.startString, e.type, where);
            }
            if (!names.insert(e.name).second)
                throw Error(fmu + ": variable '" + e.name
                            + "' is declared twice");
            md.variables.push_back(std::move(e));
        }
    }
    return md;
}

} // namespace fmuImport

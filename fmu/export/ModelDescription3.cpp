// The FMI 3.0 co-simulation modelDescription.xml and terminalsAndIcons.xml,
// from the same variable table as the FMI 2.0 description (Fmi3Variables).
#include <set>
#include <sstream>

#include "DescriptionText.hpp"
#include "Fmi3Variables.hpp"
#include "ModelDescription.hpp"

namespace fmuExport {

namespace {

//- FMI 3.0 value references of the variables holding `elements` (sorted,
//  once each), parameters left out unless `withParameters`
std::string dependencyList(const Fmi3Variables& arrays,
                           const std::vector<fmi2ValueReference>& elements,
                           bool withParameters)
{
    std::set<fmi2ValueReference> refs;
    for (fmi2ValueReference e : elements) {
        const ArrayVariable& v = arrays.owner(e);
        if (withParameters || v.first->causality != Causality::parameter) {
            refs.insert(v.valueReference);
        }
    }
    std::string out;
    for (fmi2ValueReference vr : refs) {
        out += (out.empty() ? "" : " ") + std::to_string(vr);
    }
    return out;
}

//- Every element's dependencies (they are the same for all elements of a
//  declaration, but an n x 3 array joins three)
std::vector<fmi2ValueReference> dependencies(const ArrayVariable& v,
                                             const VariableTable& table)
{
    std::vector<fmi2ValueReference> all;
    for (fmi2ValueReference e : v.elements) {
        const std::vector<fmi2ValueReference>& d
            = table.variables()[e].dependencies;
        all.insert(all.end(), d.begin(), d.end());
    }
    return all;
}

void writeVariable(std::ostringstream& x, const ArrayVariable& v,
                   const VariableTable& table)
{
    const ScalarVariable& s = *v.first;
    const bool boolean = s.type == Type::Boolean;
    x << "    <" << (boolean ? "Boolean" : "Float64") << " name=\""
      << escape(v.name) << "\" valueReference=\"" << v.valueReference
      << "\"\n      description=\"" << escape(v.description)
      << "\"\n      causality=\"" << causalityName(s.causality)
      << "\" variability=\"" << variabilityName(s.variability) << "\"";
    if (s.initial != Initial::none) {
        x << " initial=\"" << initialName(s.initial) << "\"";
    }
    if (!boolean) {
        x << " unit=\"" << escape(s.unit) << "\"";
    }
    if (s.initial != Initial::calculated) {
        x << " start=\"";
        for (std::size_t i = 0; i < v.elements.size(); ++i) {
            const double start = table.variables()[v.elements[i]].start;
            x << (i == 0 ? "" : " ")
              << (boolean ? (start != 0.0 ? "true" : "false")
                          : formatDouble(start));
        }
        x << "\"";
    }
    if (v.dimensions.empty()) {
        x << "/>\n";
        return;
    }
    x << ">\n";
    for (std::size_t n : v.dimensions) {
        x << "      <Dimension start=\"" << n << "\"/>\n";
    }
    x << "    </" << (boolean ? "Boolean" : "Float64") << ">\n";
}

} // namespace

std::string modelDescription3Xml(const Model& model)
{
    const ModelIdentity& id = model.identity();
    const VariableTable& table = model.variables();
    const Fmi3Variables arrays(table);
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<fmiModelDescription fmiVersion=\"3.0\" modelName=\""
      << escape(id.modelIdentifier) << "\"\n  instantiationToken=\""
      << modelGuid(model) << "\"\n  description=\"" << escape(id.description)
      << "\" version=\"" << escape(id.version)
      << "\" generationTool=\"foamFmiConnectors fmuExport\"\n"
      << "  variableNamingConvention=\"structured\">\n";
    x << "  <CoSimulation modelIdentifier=\"" << escape(id.modelIdentifier)
      << "\" needsExecutionTool=\"false\"\n"
      << "    canBeInstantiatedOnlyOncePerProcess=\"false\" "
         "canGetAndSetFMUState=\"true\" canSerializeFMUState=\"true\"\n"
      << "    providesDirectionalDerivative=\"false\" "
         "providesAdjointDerivatives=\"false\"\n"
      << "    canHandleVariableCommunicationStepSize=\"true\" "
         "maxOutputDerivativeOrder=\"0\"\n"
      << "    providesIntermediateUpdate=\"false\" "
         "mightReturnEarlyFromDoStep=\"false\"\n"
      << "    canReturnEarlyAfterIntermediateUpdate=\"false\" "
         "hasEventMode=\"false\"/>\n";

    x << unitsAndLogCategoriesXml(table, "fmi3");

    x << "  <ModelVariables>\n";
    for (const ArrayVariable& v : arrays.variables()) {
        writeVariable(x, v, table);
    }
    x << "  </ModelVariables>\n  <ModelStructure>\n";
    for (const bool initial : {false, true}) {
        for (const ArrayVariable& v : arrays.variables()) {
            if (v.first->causality == Causality::output) {
                x << "    <" << (initial ? "InitialUnknown" : "Output")
                  << " valueReference=\"" << v.valueReference
                  << "\" dependencies=\""
                  << dependencyList(arrays, dependencies(v, table), initial)
                  << "\"/>\n";
            }
        }
    }
    x << "  </ModelStructure>\n</fmiModelDescription>\n";
    return x.str();
}

std::string terminalsAndIconsXml(const Model& model)
{
    const Fmi3Variables arrays(model.variables());
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<fmiTerminalsAndIcons fmiVersion=\"3.0\">\n  <Terminals>\n";
    for (const char* body : {"A", "B"}) {
        const std::string prefix = std::string(body) + ".";
        x << "    <Terminal name=\"" << body
          << "\" matchingRule=\"plug\" "
             "terminalKind=\"org.foamfmi.rigidBodyConnection\"\n"
          << "      description=\"body " << body
          << ": its kinematics at the reference point (inputs), the "
             "connector's force and moment on it (outputs), its attachment "
             "(parameters)\">\n";
        for (const ArrayVariable& v : arrays.variables()) {
            if (v.name.compare(0, prefix.size(), prefix) == 0) {
                x << "      <TerminalMemberVariable variableName=\""
                  << escape(v.name) << "\" memberName=\""
                  << escape(v.name.substr(prefix.size()))
                  << "\" variableKind=\"signal\"/>\n";
            }
        }
        x << "    </Terminal>\n";
    }
    x << "  </Terminals>\n</fmiTerminalsAndIcons>\n";
    return x.str();
}

} // namespace fmuExport

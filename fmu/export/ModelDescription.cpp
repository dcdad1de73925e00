#include "ModelDescription.hpp"

#include "DescriptionText.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace fmuExport {

namespace {

std::uint64_t fnv1a(const std::string& text, std::uint64_t hash)
{
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 0x100000001b3ULL;
    }
    return hash;
}

std::string joinIndices(const std::vector<fmi2ValueReference>& refs,
                        const std::vector<ScalarVariable>& variables,
                        bool withParameters)
{
    std::string out;
    for (fmi2ValueReference vr : refs) {
        if (!withParameters
            && variables[vr].causality == Causality::parameter) {
            continue;
        }
        out += (out.empty() ? "" : " ") + std::to_string(vr + 1);
    }
    return out;
}

} // namespace

std::string formatDouble(double value)
{
    char buffer[32];
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
        if (!std::isfinite(value) || std::strtod(buffer, nullptr) == value) {
            break;
        }
    }
    return buffer;
}

std::string modelGuid(const Model& model)
{
    const ModelIdentity& id = model.identity();
    std::ostringstream text;
    text << id.modelIdentifier << '\n'
         << id.version << '\n'
         << id.description << '\n';
    for (const ScalarVariable& v : model.variables().variables()) {
        text << v.name << '|' << v.valueReference << '|'
             << (v.type == Type::Real ? "Real" : "Boolean") << '|'
             << causalityName(v.causality) << '|'
             << variabilityName(v.variability) << '|' << initialName(v.initial)
             << '|' << v.unit << '|' << v.description << '|'
             << formatDouble(v.start) << '|';
        for (fmi2ValueReference d : v.dependencies) {
            text << d << ' ';
        }
        text << '\n';
    }
    const std::uint64_t h1 = fnv1a(text.str(), 0xcbf29ce484222325ULL);
    const std::uint64_t h2 = fnv1a(text.str(), h1 ^ 0x9e3779b97f4a7c15ULL);
    char guid[40];
    std::snprintf(guid, sizeof guid, "{%08x-%04x-%04x-%04x-%012llx}",
                  unsigned(h1 >> 32), unsigned((h1 >> 16) & 0xffff),
                  unsigned(h1 & 0xffff), unsigned(h2 >> 48),
                  static_cast<unsigned long long>(h2 & 0xffffffffffffULL));
    return guid;
}

std::string modelDescriptionXml(const Model& model)
{
    const ModelIdentity& id = model.identity();
    const std::vector<ScalarVariable>& variables
        = model.variables().variables();
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<fmiModelDescription fmiVersion=\"2.0\" modelName=\""
      << escape(id.modelIdentifier) << "\" guid=\"" << modelGuid(model)
      << "\"\n  description=\"" << escape(id.description) << "\" version=\""
      << escape(id.version)
      << "\" generationTool=\"foamFmiConnectors fmuExport\"\n"
      << "  variableNamingConvention=\"structured\" "
         "numberOfEventIndicators=\"0\">\n";
    x << "  <CoSimulation modelIdentifier=\"" << escape(id.modelIdentifier)
      << "\" needsExecutionTool=\"false\"\n"
      << "    canHandleVariableCommunicationStepSize=\"true\" "
         "canInterpolateInputs=\"false\"\n"
      << "    maxOutputDerivativeOrder=\"0\" canRunAsynchronuously=\"false\"\n"
      << "    canBeInstantiatedOnlyOncePerProcess=\"false\" "
         "canNotUseMemoryManagementFunctions=\"true\"\n"
      << "    canGetAndSetFMUstate=\"true\" canSerializeFMUstate=\"true\" "
         "providesDirectionalDerivative=\"false\"/>\n";

    x << unitsAndLogCategoriesXml(model.variables(), "fmi2");

    x << "  <ModelVariables>\n";
    for (const ScalarVariable& v : variables) {
        x << "    <!-- index " << v.valueReference + 1 << " -->\n"
          << "    <ScalarVariable name=\"" << escape(v.name)
          << "\" valueReference=\"" << v.valueReference << "\"\n"
          << "      description=\"" << escape(v.description)
          << "\"\n      causality=\"" << causalityName(v.causality)
          << "\" variability=\"" << variabilityName(v.variability) << "\"";
        if (v.initial != Initial::none) {
            x << " initial=\"" << initialName(v.initial) << "\"";
        }
        if (v.type == Type::Boolean) {
            x << ">\n      <Boolean start=\""
              << (v.start != 0.0 ? "true" : "false") << "\"";
        } else {
            x << ">\n      <Real unit=\"" << escape(v.unit) << "\"";
            if (v.initial != Initial::calculated) {
                x << " start=\"" << formatDouble(v.start) << "\"";
            }
        }
        x << "/>\n    </ScalarVariable>\n";
    }
    x << "  </ModelVariables>\n";

    // Every output as an Unknown, its dependencies those at initialization
    // or not
    const auto unknowns = [&](bool initialization) {
        for (const ScalarVariable& v : variables) {
            if (v.causality == Causality::output) {
                x << "      <Unknown index=\"" << v.valueReference + 1
                  << "\" dependencies=\""
                  << joinIndices(v.dependencies, variables, initialization)
                  << "\"/>\n";
            }
        }
    };
    x << "  <ModelStructure>\n    <Outputs>\n";
    unknowns(false);
    x << "    </Outputs>\n    <InitialUnknowns>\n";
    unknowns(true);
    x << "    </InitialUnknowns>\n  </ModelStructure>\n"
      << "</fmiModelDescription>\n";
    return x.str();
}

std::string documentationHtml(const Model& model)
{
    const ModelIdentity& id = model.identity();
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta "
         "charset=\"utf-8\">\n"
      << "<title>" << escape(id.modelIdentifier) << "</title>\n"
      << "<style>table{border-collapse:collapse}td,th{border:1px solid #999;"
         "padding:2px 6px}</style>\n</head>\n<body>\n"
      << "<h1>" << escape(id.modelIdentifier) << "</h1>\n<p>"
      << escape(id.description) << "</p>\n<p>Version " << escape(id.version)
      << ", GUID <code>" << modelGuid(model) << "</code>. FMI 2.0 "
      << "co-simulation; global frame, SI units, moments about each body's "
         "reference point.</p>\n<h2>Law</h2>\n"
      << id.lawHtml << "\n<h2>Variables</h2>\n<table>\n"
      << "<tr><th>name</th><th>value reference</th><th>causality</th>"
         "<th>unit</th><th>start</th><th>description</th></tr>\n";
    for (const ScalarVariable& v : model.variables().variables()) {
        h << "<tr><td><code>" << escape(v.name) << "</code></td><td>"
          << v.valueReference << "</td><td>" << causalityName(v.causality)
          << "</td><td>" << escape(v.unit) << "</td><td>"
          << (v.initial == Initial::calculated ? std::string()
                  : v.type == Type::Boolean
                  ? std::string(v.start != 0.0 ? "true" : "false")
                  : formatDouble(v.start))
          << "</td><td>" << escape(v.description) << "</td></tr>\n";
    }
    h << "</table>\n</body>\n</html>\n";
    return h.str();
}

} // namespace fmuExport

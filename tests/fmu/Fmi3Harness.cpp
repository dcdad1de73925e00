#include "Fmi3Harness.hpp"

#include <stdexcept>

#include "FmuHarness.hpp"
#include "Unzip.hpp"

namespace fmuTest {

namespace {

void recordLog(fmi3InstanceEnvironment env, fmi3Status status,
               fmi3String category, fmi3String message)
{
    static_cast<std::vector<LogRecord3>*>(env)->push_back(
        {status, category ? category : "", message ? message : ""});
}

} // namespace

std::string fmu3Path(const std::string& name)
{
    return std::string(FOAMFMI_FMU_DIR) + "/fmi3/" + name + ".fmu";
}

LoadedFmu3::LoadedFmu3(const std::string& modelName)
    : UnpackedFmu(modelName, fmu3Path(modelName))
{
    const std::string t = "terminalsAndIcons/terminalsAndIcons.xml";
    fmuImport::FmuArchive archive(fmu3Path(name),
                                  fmuImport::UnpackLimits::fromEnvironment());
    const std::string text = archive.read(t);
    if (!terminals.load_buffer(text.data(), text.size())) {
        throw std::runtime_error("cannot parse " + t + " of " + fmu3Path(name));
    }
    token = modelDescription().guid;
    for (const fmuImport::Variable& e : modelDescription().variables) {
        if (e.element == 0) {
            Variable3 v;
            v.name = e.arrayName.empty() ? e.name : e.arrayName;
            v.valueReference = e.arrayValueReference;
            v.type = e.typeName;
            v.causality = e.causality;
            v.dimensions = e.dimensions;
            for (const std::size_t n : v.dimensions) {
                v.size *= n;
            }
            variables.push_back(v);
        }
        if (e.hasStart) {
            variables.back().start.push_back(e.start);
        }
    }
    static_cast<fmuImport::Fmi3Api&>(api) = loadLibrary().api3();
#define FMU_TEST_RESOLVE(function) resolve("fmi3" #function, api.function);
    FMU_TEST_FMI3_OTHER_FUNCTIONS(FMU_TEST_RESOLVE)
#undef FMU_TEST_RESOLVE
}

const Variable3& LoadedFmu3::variable(const std::string& variableName) const
{
    for (const Variable3& v : variables) {
        if (v.name == variableName) {
            return v;
        }
    }
    throw std::runtime_error(name + " (FMI 3.0) has no variable "
                             + variableName);
}

Instance3::Instance3(const LoadedFmu3& fmu, const char* token) : fmu_(fmu)
{
    c = fmu.api.InstantiateCoSimulation(
        "test", token ? token : fmu.token.c_str(), nullptr, false, false, false,
        false, nullptr, 0, &log, recordLog, nullptr);
}

Instance3::~Instance3()
{
    if (c != nullptr) {
        fmu_.api.FreeInstance(c);
    }
}

fmi3Status Instance3::initialize(
    const std::map<std::string, std::vector<double>>& parameters)
{
    fmi3Status s
        = fmu_.api.EnterInitializationMode(c, false, 0.0, 0.0, false, 0.0);
    if (s == fmi3OK) {
        s = set(parameters);
    }
    return s == fmi3OK ? fmu_.api.ExitInitializationMode(c) : s;
}

fmi3Status
Instance3::set(const std::map<std::string, std::vector<double>>& values)
{
    std::vector<fmi3ValueReference> refs;
    std::vector<double> v;
    for (const auto& [name, value] : values) {
        refs.push_back(fmu_.variable(name).valueReference);
        v.insert(v.end(), value.begin(), value.end());
    }
    return fmu_.api.SetFloat64(c, refs.data(), refs.size(), v.data(), v.size());
}

std::vector<double> Instance3::get(const std::string& name)
{
    const Variable3& v = fmu_.variable(name);
    std::vector<double> values(v.size);
    if (fmu_.api.GetFloat64(c, &v.valueReference, 1, values.data(),
                            values.size())
        != fmi3OK) {
        throw std::runtime_error("fmi3GetFloat64(" + name
                                 + ") failed: " + lastMessage());
    }
    return values;
}

fmi3Status Instance3::doStep(double t, double h)
{
    fmi3Boolean event = true, terminate = true, early = true;
    fmi3Float64 last = -1.0;
    const fmi3Status s
        = fmu_.api.DoStep(c, t, h, false, &event, &terminate, &early, &last);
    if (s == fmi3OK && (event || terminate || early || last != t + h)) {
        throw std::runtime_error("fmi3DoStep: unexpected flags or "
                                 "lastSuccessfulTime");
    }
    return s;
}

std::vector<std::string> fmi2ElementNames(const Variable3& v)
{
    const auto index = [](std::size_t i) { return std::to_string(i + 1); };
    std::vector<std::string> names;
    if (v.dimensions.empty()) {
        names.push_back(v.name);
    } else if (v.dimensions.size() == 1) {
        for (std::size_t i = 0; i < v.dimensions[0]; ++i) {
            names.push_back(v.name + "[" + index(i) + "]");
        }
    } else {
        for (std::size_t i = 0; i < v.dimensions[0]; ++i) {
            for (std::size_t j = 0; j < v.dimensions[1]; ++j) {
                names.push_back(v.name + "[" + index(i) + "," + index(j) + "]");
            }
        }
    }
    return names;
}

std::map<std::string, std::vector<double>>
arrayValues(const std::map<std::string, double>& scalars,
            const LoadedFmu3& fmu3)
{
    std::map<std::string, std::vector<double>> arrays;
    std::size_t used = 0;
    for (const Variable3& v : fmu3.variables) {
        const std::vector<std::string> names = fmi2ElementNames(v);
        std::vector<double> values = v.start;
        values.resize(names.size());
        bool any = false;
        for (std::size_t i = 0; i < names.size(); ++i) {
            const auto it = scalars.find(names[i]);
            if (it != scalars.end()) {
                values[i] = it->second;
                any = true;
                ++used;
            }
        }
        if (any) {
            arrays[v.name] = values;
        }
    }
    if (used != scalars.size()) {
        throw std::runtime_error("arrayValues: a scalar is in no FMI 3.0 "
                                 "variable");
    }
    return arrays;
}

std::string Instance3::lastMessage() const
{
    return log.empty() ? std::string() : log.back().message;
}

} // namespace fmuTest

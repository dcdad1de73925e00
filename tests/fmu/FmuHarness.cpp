#include "FmuHarness.hpp"

#include <cstdarg>
#include <cstdio>
#include <stdexcept>

namespace fmuTest {

namespace {

void recordLog(fmi2ComponentEnvironment env, fmi2String, fmi2Status status,
               fmi2String category, fmi2String format, ...)
{
    char buffer[2048];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    static_cast<std::vector<LogRecord>*>(env)->push_back(
        {status, category ? category : "", buffer});
}

} // namespace

std::string fmuPath(const std::string& name)
{
    return std::string(FOAMFMI_FMU_DIR) + "/" + name + ".fmu";
}

LoadedFmu::LoadedFmu(const std::string& modelName)
    : UnpackedFmu(modelName, fmuPath(modelName))
{
    guid = modelDescription().guid;
    for (const fmuImport::Variable& v : modelDescription().variables) {
        vr[v.name] = v.valueReference;
    }
    static_cast<fmuImport::Fmi2Api&>(api) = loadLibrary().api();
#define FMU_TEST_RESOLVE(function) resolve("fmi2" #function, api.function);
    FMU_TEST_FMI2_MODEL_EXCHANGE_FUNCTIONS(FMU_TEST_RESOLVE)
#undef FMU_TEST_RESOLVE
}

fmi2ValueReference LoadedFmu::ref(const std::string& variable) const
{
    const auto it = vr.find(variable);
    if (it == vr.end()) {
        throw std::runtime_error(name + " has no variable " + variable);
    }
    return it->second;
}

Instance::Instance(const LoadedFmu& fmu, const char* guid, fmi2Type type)
    : fmu_(fmu)
{
    callbacks_.logger = recordLog;
    callbacks_.allocateMemory = nullptr;
    callbacks_.freeMemory = nullptr;
    callbacks_.stepFinished = nullptr;
    callbacks_.componentEnvironment = &log;
    c = fmu.api.Instantiate("test", type, guid ? guid : fmu.guid.c_str(), "",
                            &callbacks_, fmi2False, fmi2False);
}

Instance::~Instance()
{
    if (c != nullptr) {
        fmu_.api.FreeInstance(c);
    }
}

fmi2Status Instance::initialize(const std::map<std::string, double>& parameters)
{
    fmi2Status s
        = fmu_.api.SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
    if (s == fmi2OK) {
        s = fmu_.api.EnterInitializationMode(c);
    }
    if (s == fmi2OK) {
        s = set(parameters);
    }
    return s == fmi2OK ? fmu_.api.ExitInitializationMode(c) : s;
}

std::vector<fmi2Byte> Instance::serialize(fmi2FMUstate state)
{
    std::size_t size = 0;
    if (fmu_.api.SerializedFMUstateSize(c, state, &size) != fmi2OK) {
        return {};
    }
    std::vector<fmi2Byte> bytes(size);
    if (fmu_.api.SerializeFMUstate(c, state, bytes.data(), size) != fmi2OK) {
        return {};
    }
    return bytes;
}

fmi2Status Instance::restore(const std::vector<fmi2Byte>& bytes)
{
    fmi2FMUstate state = nullptr;
    fmi2Status s
        = fmu_.api.DeSerializeFMUstate(c, bytes.data(), bytes.size(), &state);
    if (s == fmi2OK) {
        s = fmu_.api.SetFMUstate(c, state);
        fmu_.api.FreeFMUstate(c, &state);
    }
    return s;
}

fmi2Status Instance::set(const std::map<std::string, double>& values)
{
    std::vector<fmi2ValueReference> refs;
    std::vector<double> v;
    for (const auto& [name, value] : values) {
        refs.push_back(fmu_.ref(name));
        v.push_back(value);
    }
    return fmu_.api.SetReal(c, refs.data(), refs.size(), v.data());
}

fmi2Status Instance::get(const std::vector<std::string>& names,
                         std::vector<double>& values)
{
    std::vector<fmi2ValueReference> refs;
    for (const std::string& name : names) {
        refs.push_back(fmu_.ref(name));
    }
    values.resize(names.size());
    return fmu_.api.GetReal(c, refs.data(), refs.size(), values.data());
}

double Instance::get(const std::string& name)
{
    std::vector<double> v;
    if (get({name}, v) != fmi2OK) {
        throw std::runtime_error("fmi2GetReal(" + name
                                 + ") failed: " + lastMessage());
    }
    return v[0];
}

std::string Instance::lastMessage() const
{
    return log.empty() ? std::string() : log.back().message;
}

const std::vector<std::string>& connectorOutputs()
{
    static const std::vector<std::string> names = {
        "A.F[1]",          "A.F[2]",         "A.F[3]", "A.M[1]",     "A.M[2]",
        "A.M[3]",          "B.F[1]",         "B.F[2]", "B.F[3]",     "B.M[1]",
        "B.M[2]",          "B.M[3]",         "length", "lengthRate", "tension",
        "potentialEnergy", "dissipatedPower"};
    return names;
}

std::string onBinary(const std::string& tool, const LoadedFmu& fmu)
{
    const std::string command = tool + " '"
        + (fmu.directory / "binaries/linux64" / (fmu.name + ".so")).string()
        + "'";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"),
                                               pclose);
    std::string text;
    char buffer[512];
    while (pipe && fgets(buffer, sizeof buffer, pipe.get()) != nullptr) {
        text += buffer;
    }
    return text;
}

} // namespace fmuTest

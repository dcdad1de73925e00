// Test harness for connector FMUs through their C entry points: unzips a
// .fmu into a temporary directory, dlopens binaries/linux64/<name>.so,
// resolves every fmi2 function by name and reads modelDescription.xml.
#ifndef TESTS_FMU_FMUHARNESS_HPP
#define TESTS_FMU_FMUHARNESS_HPP

#include <pugixml.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "fmi2Functions.h"

namespace fmuTest {

// Every function of fmi2Functions.h (44), without the fmi2 prefix
// clang-format off
#define FMU_TEST_FMI2_FUNCTIONS(X) \
    X(GetTypesPlatform) \
    X(GetVersion) \
    X(SetDebugLogging) \
    X(Instantiate) \
    X(FreeInstance) \
    X(SetupExperiment) \
    X(EnterInitializationMode) \
    X(ExitInitializationMode) \
    X(Terminate) \
    X(Reset) \
    X(GetReal) \
    X(GetInteger) \
    X(GetBoolean) \
    X(GetString) \
    X(SetReal) \
    X(SetInteger) \
    X(SetBoolean) \
    X(SetString) \
    X(GetFMUstate) \
    X(SetFMUstate) \
    X(FreeFMUstate) \
    X(SerializedFMUstateSize) \
    X(SerializeFMUstate) \
    X(DeSerializeFMUstate) \
    X(GetDirectionalDerivative) \
    X(EnterEventMode) \
    X(NewDiscreteStates) \
    X(EnterContinuousTimeMode) \
    X(CompletedIntegratorStep) \
    X(SetTime) \
    X(SetContinuousStates) \
    X(GetDerivatives) \
    X(GetEventIndicators) \
    X(GetContinuousStates) \
    X(GetNominalsOfContinuousStates) \
    X(SetRealInputDerivatives) \
    X(GetRealOutputDerivatives) \
    X(DoStep) \
    X(CancelStep) \
    X(GetStatus) \
    X(GetRealStatus) \
    X(GetIntegerStatus) \
    X(GetBooleanStatus) \
    X(GetStringStatus)
// clang-format on

struct Fmi2Api {
#define FMU_TEST_DECLARE(name) fmi2##name##TYPE* name = nullptr;
    FMU_TEST_FMI2_FUNCTIONS(FMU_TEST_DECLARE)
#undef FMU_TEST_DECLARE
};

//- Extracts every file of a zip archive (an .fmu) into `target`
void unzip(const std::string& archive, const std::filesystem::path& target);

//- Extracts an .fmu into a new temporary directory, returned
std::filesystem::path unpack(const std::string& archive);

//- Path of <FOAMFMI_FMU_DIR>/<name>.fmu
std::string fmuPath(const std::string& name);

class LoadedFmu {
public:
    explicit LoadedFmu(const std::string& name);
    ~LoadedFmu();
    LoadedFmu(const LoadedFmu&) = delete;
    LoadedFmu& operator=(const LoadedFmu&) = delete;

    Fmi2Api api;
    //- fmi2 functions that dlsym did not find
    std::vector<std::string> missing;
    std::string name;
    std::string guid;
    pugi::xml_document description;
    //- ScalarVariable name -> value reference
    std::map<std::string, fmi2ValueReference> vr;
    std::filesystem::path directory;

    fmi2ValueReference ref(const std::string& variable) const;

private:
    void* library_ = nullptr;
};

//- Logger messages of one instance
struct LogRecord {
    fmi2Status status;
    std::string category;
    std::string message;
};

//- An instance with its own log; freed on destruction
class Instance {
public:
    //- Instantiates with the FMU's GUID, or `guid` if given
    explicit Instance(const LoadedFmu& fmu, const char* guid = nullptr,
                      fmi2Type type = fmi2CoSimulation);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    fmi2Component c = nullptr;
    std::vector<LogRecord> log;

    //- Instantiated -> stepComplete, with parameters set in between
    fmi2Status initialize(const std::map<std::string, double>& parameters);
    fmi2Status set(const std::map<std::string, double>& values);
    fmi2Status get(const std::vector<std::string>& names,
                   std::vector<double>& values);
    double get(const std::string& name);
    //- Last logged message ("" if none)
    std::string lastMessage() const;
    //- The FMU state `state` of this instance as serialized bytes (empty
    //  where the FMU refuses)
    std::vector<fmi2Byte> serialize(fmi2FMUstate state);
    //- This instance set to the state serialized in `bytes` (a restart)
    fmi2Status restore(const std::vector<fmi2Byte>& bytes);

private:
    const LoadedFmu& fmu_;
    fmi2CallbackFunctions callbacks_;
};

//- Names of the 17 outputs of the connector interface, in order
const std::vector<std::string>& connectorOutputs();

} // namespace fmuTest

#endif

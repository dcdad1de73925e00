// Test harness for connector FMUs through their C entry points. The FMU is
// unpacked, its modelDescription.xml read and its binary loaded by the
// importer (fmuImport: Fmu::Impl, Library); the harness adds what tests of
// the C API need: the raw function pointers (to call every fmi2 function,
// in any order, with any arguments), the model-exchange functions the
// importer does not resolve, and the XML text as a document.
#ifndef TESTS_FMU_FMUHARNESS_HPP
#define TESTS_FMU_FMUHARNESS_HPP

#include <pugixml.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "UnpackedFmu.hpp"
#include "fmi2Functions.h"

namespace fmuTest {

// The fmi2 functions of model exchange (FMI 2.0, section 3.2), without the
// fmi2 prefix: fmuImport::Fmi2Api has the common and co-simulation ones
// clang-format off
#define FMU_TEST_FMI2_MODEL_EXCHANGE_FUNCTIONS(X) \
    X(EnterEventMode) \
    X(NewDiscreteStates) \
    X(EnterContinuousTimeMode) \
    X(CompletedIntegratorStep) \
    X(SetTime) \
    X(SetContinuousStates) \
    X(GetDerivatives) \
    X(GetEventIndicators) \
    X(GetContinuousStates) \
    X(GetNominalsOfContinuousStates)
// clang-format on

//- Every function of fmi2Functions.h
struct Fmi2Api : fmuImport::Fmi2Api {
#define FMU_TEST_DECLARE(name) fmi2##name##TYPE* name = nullptr;
    FMU_TEST_FMI2_MODEL_EXCHANGE_FUNCTIONS(FMU_TEST_DECLARE)
#undef FMU_TEST_DECLARE
};

//- Path of <FOAMFMI_FMU_DIR>/<name>.fmu
std::string fmuPath(const std::string& name);

//- <FOAMFMI_FMU_DIR>/<name>.fmu unpacked (UnpackedFmu) and its binary
//  loaded; `missing`: the model-exchange fmi2 functions it does not export
class LoadedFmu : public UnpackedFmu {
public:
    explicit LoadedFmu(const std::string& name);

    Fmi2Api api;
    std::string guid;
    //- ScalarVariable name -> value reference
    std::map<std::string, fmi2ValueReference> vr;

    fmi2ValueReference ref(const std::string& variable) const;
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

//- Output of `tool '<binary>'` on the binary of an unpacked FMU
//  (binaries/linux64/<name>.so)
std::string onBinary(const std::string& tool, const LoadedFmu& fmu);

//- Names of the 17 outputs of the connector interface, in order
const std::vector<std::string>& connectorOutputs();

} // namespace fmuTest

#endif

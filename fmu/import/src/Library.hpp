// The FMU's shared library: dlopen and every fmi2 (FMI 2.0) or fmi3 (FMI
// 3.0) function of a co-simulation FMU that the importer calls resolved.
#ifndef FMUIMPORT_LIBRARY_HPP
#define FMUIMPORT_LIBRARY_HPP

#include "fmi2FunctionTypes.h"
#include "fmi3FunctionTypes.h"

#include <string>

namespace fmuImport {

// The functions a co-simulation FMU exports (FMI 2.0, section 2.1.2 and
// 4.2): the common ones and those of co-simulation. The model-exchange
// functions are not asked for: a co-simulation-only FMU need not have them.
// clang-format off
#define FMUIMPORT_FMI2_FUNCTIONS(X) \
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

// FMI 3.0 (section 2.3 and 4.2): the functions of co-simulation that the
// importer calls; the model-exchange, scheduled-execution, clock, event
// and derivative functions are not asked for.
// clang-format off
#define FMUIMPORT_FMI3_FUNCTIONS(X) \
    X(GetVersion) \
    X(SetDebugLogging) \
    X(InstantiateCoSimulation) \
    X(FreeInstance) \
    X(EnterInitializationMode) \
    X(ExitInitializationMode) \
    X(Terminate) \
    X(Reset) \
    X(GetFloat32) X(GetFloat64) \
    X(GetInt8) X(GetUInt8) X(GetInt16) X(GetUInt16) \
    X(GetInt32) X(GetUInt32) X(GetInt64) X(GetUInt64) \
    X(GetBoolean) X(GetString) X(GetBinary) \
    X(SetFloat32) X(SetFloat64) \
    X(SetInt8) X(SetUInt8) X(SetInt16) X(SetUInt16) \
    X(SetInt32) X(SetUInt32) X(SetInt64) X(SetUInt64) \
    X(SetBoolean) X(SetString) X(SetBinary) \
    X(GetFMUState) \
    X(SetFMUState) \
    X(FreeFMUState) \
    X(SerializedFMUStateSize) \
    X(SerializeFMUState) \
    X(DeserializeFMUState) \
    X(DoStep)
// clang-format on

struct Fmi3Api {
#define FMUIMPORT_DECLARE(name) fmi3##name##TYPE* name = nullptr;
    FMUIMPORT_FMI3_FUNCTIONS(FMUIMPORT_DECLARE)
#undef FMUIMPORT_DECLARE
};

struct Fmi2Api {
#define FMUIMPORT_DECLARE(name) fmi2##name##TYPE* name = nullptr;
    FMUIMPORT_FMI2_FUNCTIONS(FMUIMPORT_DECLARE)
#undef FMUIMPORT_DECLARE
};

class Library {
public:
    // Loads file with RTLD_LOCAL | RTLD_NOW and resolves the common and
    // co-simulation functions of FMI fmiMajorVersion (2: fmi2, 3: fmi3);
    // errors name fmuPath and the missing functions.
    Library(const std::string& file, const std::string& fmuPath,
            int fmiMajorVersion);
    ~Library();
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;

    const Fmi2Api& api() const { return api_; }
    const Fmi3Api& api3() const { return api3_; }

    // The address the binary exports under name (dlsym), nullptr if none:
    // for a function outside the lists above (the tests of the FMUs' C
    // API call the model-exchange ones)
    void* symbol(const char* name) const;

private:
    void* handle_ = nullptr;
    Fmi2Api api_; // resolved for FMI 2.0
    Fmi3Api api3_; // resolved for FMI 3.0
};

} // namespace fmuImport

#endif

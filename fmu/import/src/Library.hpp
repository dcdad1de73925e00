// The FMU's shared library: dlopen and every fmi2 function a co-simulation
// FMU exports resolved.
#ifndef FMUIMPORT_LIBRARY_HPP
#define FMUIMPORT_LIBRARY_HPP

#include "fmi2FunctionTypes.h"

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

struct Fmi2Api {
#define FMUIMPORT_DECLARE(name) fmi2##name##TYPE* name = nullptr;
    FMUIMPORT_FMI2_FUNCTIONS(FMUIMPORT_DECLARE)
#undef FMUIMPORT_DECLARE
};

class Library {
public:
    // Loads file with RTLD_LOCAL | RTLD_NOW and resolves the common and
    // co-simulation fmi2 functions; errors name fmuPath and the missing
    // functions.
    Library(const std::string& file, const std::string& fmuPath);
    ~Library();
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;

    const Fmi2Api& api() const { return api_; }

private:
    void* handle_ = nullptr;
    Fmi2Api api_;
};

} // namespace fmuImport

#endif

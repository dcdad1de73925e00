// The fmi2 C entry points of every connector FMU: instances, modes and
// values. Compiled into each FMU binary (not into the static export library)
// so that the linker keeps them; they are the only symbols the binary
// exports. fmi2CoSimulation.cpp has the rest.
#include <cstring>
#include <new>
#include <string>

#include "EntryPoints.hpp"
#include "ModelDescription.hpp"
#include "fmi2Functions.h"

namespace {

using fmuExport::anyLiveState;
using fmuExport::FmuInstance;
using fmuExport::guarded;
using fmuExport::readableState;
using fmuExport::writableState;

void logInstantiateError(const fmi2CallbackFunctions* functions,
                         fmi2String instanceName, const char* message) noexcept
{
    if (functions == nullptr || functions->logger == nullptr) {
        return;
    }
    const char* name = instanceName ? instanceName : "";
    try {
        functions->logger(functions->componentEnvironment, name, fmi2Error,
                          fmuExport::logCategoryError, "fmi2Instantiate: %s",
                          message);
    } catch (...) {
        // A throwing logger must not take the importer down with it.
    }
}

} // namespace

extern "C" {

const char* fmi2GetTypesPlatform(void)
{
    return fmi2TypesPlatform;
}

const char* fmi2GetVersion(void)
{
    return fmi2Version;
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn,
                               size_t nCategories,
                               const fmi2String categories[])
{
    return guarded(c, "fmi2SetDebugLogging", anyLiveState, [&] {
        static_cast<FmuInstance*>(c)->setDebugLogging(loggingOn != fmi2False,
                                                      nCategories, categories);
    });
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType,
                              fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions* functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn)
{
    (void)fmuResourceLocation;
    (void)visible;
    try {
        if (functions == nullptr) {
            return nullptr;
        }
        if (instanceName == nullptr || instanceName[0] == '\0') {
            logInstantiateError(functions, instanceName,
                                "instanceName must be a non-empty string");
            return nullptr;
        }
        std::unique_ptr<fmuExport::Model> model = fmuExport::createModel();
        const std::string name = model->identity().modelIdentifier;
        if (fmuType != fmi2CoSimulation) {
            const std::string message = name
                + " supports co-simulation only (fmuType fmi2CoSimulation)";
            logInstantiateError(functions, instanceName, message.c_str());
            return nullptr;
        }
        const std::string guid = fmuExport::modelGuid(*model);
        if (fmuGUID == nullptr || guid != fmuGUID) {
            const std::string message = "GUID "
                + std::string(fmuGUID ? fmuGUID : "(null)") + " does not match "
                + name + "'s GUID " + guid;
            logInstantiateError(functions, instanceName, message.c_str());
            return nullptr;
        }
        return new FmuInstance(std::move(model), instanceName, *functions,
                               loggingOn != fmi2False);
    } catch (const std::exception& e) {
        logInstantiateError(functions, instanceName, e.what());
    } catch (...) {
        logInstantiateError(functions, instanceName, "unknown exception");
    }
    return nullptr;
}

void fmi2FreeInstance(fmi2Component c)
{
    delete static_cast<FmuInstance*>(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    return guarded(c, "fmi2SetupExperiment", fmuExport::instantiated, [&] {
        static_cast<FmuInstance*>(c)->setupExperiment(startTime);
    });
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    return guarded(
        c, "fmi2EnterInitializationMode", fmuExport::instantiated,
        [&] { static_cast<FmuInstance*>(c)->enterInitializationMode(); });
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    return guarded(
        c, "fmi2ExitInitializationMode", fmuExport::initializationMode,
        [&] { static_cast<FmuInstance*>(c)->exitInitializationMode(); });
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    return guarded(c, "fmi2Terminate", fmuExport::stepComplete,
                   [&] { static_cast<FmuInstance*>(c)->terminate(); });
}

fmi2Status fmi2Reset(fmi2Component c)
{
    return guarded(c, "fmi2Reset", anyLiveState,
                   [&] { static_cast<FmuInstance*>(c)->reset(); });
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[],
                       size_t nvr, fmi2Real value[])
{
    return guarded(c, "fmi2GetReal", readableState, [&] {
        static_cast<FmuInstance*>(c)->getReal(vr, nvr, value);
    });
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                          size_t nvr, fmi2Boolean value[])
{
    return guarded(c, "fmi2GetBoolean", readableState, [&] {
        static_cast<FmuInstance*>(c)->getBoolean(vr, nvr, value);
    });
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[],
                       size_t nvr, const fmi2Real value[])
{
    return guarded(c, "fmi2SetReal", writableState, [&] {
        static_cast<FmuInstance*>(c)->setReal(vr, nvr, value);
    });
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                          size_t nvr, const fmi2Boolean[])
{
    return guarded(c, "fmi2SetBoolean", writableState,
                   [&] { static_cast<FmuInstance*>(c)->setBoolean(vr, nvr); });
}

// The types no connector declares: every value reference is refused
#define FMU_EXPORT_NO_VARIABLES(Function, mask, Values)                        \
    fmi2Status fmi2##Function(fmi2Component c, const fmi2ValueReference vr[],  \
                              size_t nvr, Values)                              \
    {                                                                          \
        return guarded(c, "fmi2" #Function, mask, [&] {                        \
            static_cast<FmuInstance*>(c)->rejectValueReferences(#Function + 3, \
                                                                vr, nvr);      \
        });                                                                    \
    }

FMU_EXPORT_NO_VARIABLES(GetInteger, readableState, fmi2Integer[])
FMU_EXPORT_NO_VARIABLES(GetString, readableState, fmi2String[])
FMU_EXPORT_NO_VARIABLES(SetInteger, writableState, const fmi2Integer[])
FMU_EXPORT_NO_VARIABLES(SetString, writableState, const fmi2String[])

} // extern "C"

// The fmi3 C entry points of every connector FMU: version, instances and
// modes. Compiled into each FMI 3.0 binary, whose only exports they are
// with those of fmi3Values.cpp (values) and fmi3CoSimulation.cpp (FMU
// states, stepping, the functions that do not apply).
#include <memory>
#include <string>

#include "EntryPoints3.hpp"
#include "ModelDescription.hpp"
#include "fmi3Functions.h"

namespace {

using fmuExport::anyLiveState;
using fmuExport::Fmi3Instance;
using fmuExport::guarded3;

void logInstantiateError(fmi3InstanceEnvironment environment,
                         fmi3LogMessageCallback logMessage,
                         const char* function, const std::string& message)
{
    if (logMessage == nullptr) {
        return;
    }
    try {
        logMessage(environment, fmi3Error, fmuExport::logCategoryError,
                   (std::string(function) + ": " + message).c_str());
    } catch (...) {
        // A throwing logger must not take the importer down with it.
    }
}

fmi3Instance refuse(fmi3InstanceEnvironment environment,
                    fmi3LogMessageCallback logMessage, const char* function)
{
    try {
        logInstantiateError(environment, logMessage, function,
                            fmuExport::createModel()->identity().modelIdentifier
                                + " supports co-simulation only "
                                  "(fmi3InstantiateCoSimulation)");
    } catch (...) {
    }
    return nullptr;
}

} // namespace

extern "C" {

const char* fmi3GetVersion(void)
{
    return fmi3Version;
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
                               size_t nCategories,
                               const fmi3String categories[])
{
    return guarded3(
        instance, "fmi3SetDebugLogging", anyLiveState, [&](Fmi3Instance& i) {
            i.core().setDebugLogging(loggingOn, nCategories, categories);
        });
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String, fmi3String, fmi3String,
                                          fmi3Boolean, fmi3Boolean,
                                          fmi3InstanceEnvironment environment,
                                          fmi3LogMessageCallback logMessage)
{
    return refuse(environment, logMessage, "fmi3InstantiateModelExchange");
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken,
    fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
    fmi3Boolean eventModeUsed, fmi3Boolean earlyReturnAllowed,
    const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment environment,
    fmi3LogMessageCallback logMessage,
    fmi3IntermediateUpdateCallback intermediateUpdate)
{
    (void)resourcePath;
    (void)visible;
    (void)earlyReturnAllowed;
    (void)requiredIntermediateVariables;
    (void)intermediateUpdate;
    const char* function = "fmi3InstantiateCoSimulation";
    try {
        if (instanceName == nullptr || instanceName[0] == '\0') {
            logInstantiateError(environment, logMessage, function,
                                "instanceName must be a non-empty string");
            return nullptr;
        }
        std::unique_ptr<fmuExport::Model> model = fmuExport::createModel();
        const std::string name = model->identity().modelIdentifier;
        if (eventModeUsed) {
            logInstantiateError(environment, logMessage, function,
                                name
                                    + " has no event mode (hasEventMode is "
                                      "false): eventModeUsed must be false");
            return nullptr;
        }
        if (nRequiredIntermediateVariables != 0) {
            logInstantiateError(environment, logMessage, function,
                                name + " provides no intermediate update");
            return nullptr;
        }
        const std::string token = fmuExport::modelGuid(*model);
        if (instantiationToken == nullptr || token != instantiationToken) {
            logInstantiateError(
                environment, logMessage, function,
                "instantiationToken "
                    + std::string(instantiationToken ? instantiationToken
                                                     : "(null)")
                    + " does not match " + name + "'s " + token);
            return nullptr;
        }
        return new Fmi3Instance(std::move(model), instanceName, environment,
                                logMessage, loggingOn);
    } catch (const std::exception& e) {
        logInstantiateError(environment, logMessage, function, e.what());
    } catch (...) {
        logInstantiateError(environment, logMessage, function,
                            "unknown exception");
    }
    return nullptr;
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean,
    fmi3InstanceEnvironment environment, fmi3LogMessageCallback logMessage,
    fmi3ClockUpdateCallback, fmi3LockPreemptionCallback,
    fmi3UnlockPreemptionCallback)
{
    return refuse(environment, logMessage, "fmi3InstantiateScheduledExecution");
}

void fmi3FreeInstance(fmi3Instance instance)
{
    delete static_cast<Fmi3Instance*>(instance);
}

fmi3Status
fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined,
                            fmi3Float64 tolerance, fmi3Float64 startTime,
                            fmi3Boolean stopTimeDefined, fmi3Float64 stopTime)
{
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    return guarded3(instance, "fmi3EnterInitializationMode",
                    fmuExport::instantiated, [&](Fmi3Instance& i) {
                        i.core().setupExperiment(startTime);
                        i.core().enterInitializationMode();
                    });
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance)
{
    return guarded3(
        instance, "fmi3ExitInitializationMode", fmuExport::initializationMode,
        [&](Fmi3Instance& i) { i.core().exitInitializationMode(); });
}

fmi3Status fmi3Terminate(fmi3Instance instance)
{
    return guarded3(instance, "fmi3Terminate", fmuExport::stepComplete,
                    [&](Fmi3Instance& i) { i.core().terminate(); });
}

fmi3Status fmi3Reset(fmi3Instance instance)
{
    return guarded3(instance, "fmi3Reset", anyLiveState,
                    [&](Fmi3Instance& i) { i.core().reset(); });
}

} // extern "C"

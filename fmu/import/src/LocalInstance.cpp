#include "LocalInstance.hpp"

#include <cmath>
#include <sstream>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace fmuImport {

namespace {

const char* statusName(int status, bool v3 = false)
{
    static const char* const names[]
        = {"fmi2OK",    "fmi2Warning", "fmi2Discard",
           "fmi2Error", "fmi2Fatal",   "fmi2Pending"};
    static const char* const names3[]
        = {"fmi3OK", "fmi3Warning", "fmi3Discard", "fmi3Error", "fmi3Fatal"};
    if (v3)
        return status >= 0 && status <= 4 ? names3[status] : "unknown status";
    return status >= 0 && status <= 5 ? names[status] : "unknown status";
}

std::string format(const char* text, va_list args)
{
    if (!text)
        return std::string();
    va_list sizing;
    va_copy(sizing, args);
    const int n = std::vsnprintf(nullptr, 0, text, sizing);
    va_end(sizing);
    if (n < 0)
        return text;
    std::vector<char> buffer(static_cast<std::size_t>(n) + 1);
    std::vsnprintf(buffer.data(), buffer.size(), text, args);
    return std::string(buffer.data(), static_cast<std::size_t>(n));
}

// The host's code runs here, inside the FMU's call: unmarked, so that a
// crash or exit() in the host's logger is not blamed on the FMU.
extern "C" void fmuImportLogger(fmi2ComponentEnvironment environment,
                                fmi2String instanceName, fmi2Status status,
                                fmi2String category, fmi2String message, ...)
{
    const UnmarkedCallback host;
    va_list args;
    va_start(args, message);
    const std::string text = format(message, args);
    va_end(args);
    try {
        static_cast<LocalInstance*>(environment)
            ->receive(instanceName ? instanceName : "", status,
                      category ? category : "", text);
    } catch (...) {
        // An exception must not cross the FMU's C frames; the message is lost.
    }
}

const double noTime = std::numeric_limits<double>::quiet_NaN();

} // namespace

LocalInstance::LocalInstance(std::shared_ptr<Fmu::Impl> fmuImpl,
                             const std::string& path,
                             const std::string& instanceName, Logger log,
                             bool loggingOn, const FmuOptions& options)
    : Impl(std::move(fmuImpl), path, instanceName),
      v3_(fmu->description.fmiMajorVersion == 3),
      logger_(std::move(log)), site_ {
                                   siteText(path, instanceName, options.owner),
                                   options.timeout}
{
    callbacks_.logger = fmuImportLogger;
    callbacks_.allocateMemory = std::calloc;
    callbacks_.freeMemory = std::free;
    callbacks_.stepFinished = nullptr;
    callbacks_.componentEnvironment = this;
    watchCalls(options.timeout);

    try {
        admit();
    } catch (...) {
        --fmu->liveInstances; // no destructor runs
        throw;
    }
    if (v3_) {
        instantiate3(loggingOn);
        return;
    }
    const std::string resources = fmu->resourceLocation();
    component_ = call("fmi2Instantiate", noTime, api().Instantiate,
                      instanceName.c_str(), fmi2CoSimulation,
                      fmu->description.guid.c_str(), resources.c_str(),
                      &callbacks_, fmi2False, loggingOn ? fmi2True : fmi2False);
    if (!component_) {
        --fmu->liveInstances;
        std::string message = "fmi2Instantiate failed in FMU '" + fmuPath
            + "', instance '" + instanceName + "'";
        if (!lastError_.empty())
            message += ": " + lastError_;
        throw Error(message);
    }
}

LocalInstance::~LocalInstance()
{
    if (component_ && v3_)
        call("fmi3FreeInstance", time, api3().FreeInstance, component_);
    else if (component_)
        call("fmi2FreeInstance", time, api().FreeInstance, component_);
    if (admitted_)
        --fmu->liveInstances;
}

void LocalInstance::admit()
{
    const int others = fmu->liveInstances++;
    admitted_ = true;
    if (others > 0 && fmu->description.canBeInstantiatedOnlyOncePerProcess) {
        throw Error(
            "FMU '" + fmuPath
            + "' declares canBeInstantiatedOnlyOncePerProcess=\"true\" and an instance "
            + "of it exists already: cannot instantiate '" + name
            + "' (free the other instance first)");
    }
}

void LocalInstance::receive(const std::string& instanceName, int status,
                            const std::string& category,
                            const std::string& message)
{
    if (status >= fmi2Error)
        lastError_ = message;
    if (status >= fmi2Warning)
        lastNotice_ = message;
    if (logger_)
        logger_(instanceName, status, category, message);
    else
        logToStderr(instanceName, status, category, message, v3_);
}

void logToStderr(const std::string& instanceName, int status,
                 const std::string& category, const std::string& message,
                 bool fmi3)
{
    std::cerr << "[" << instanceName << "] " << statusName(status, fmi3) << " "
              << category << ": " << message << '\n';
}

void LocalInstance::check(fmi2Status status, const char* function, double t)
{
    if (status == fmi2OK)
        return;
    std::string detail;
    if (!std::isnan(t)) {
        std::ostringstream s;
        s.precision(17);
        s << " at t = " << t;
        detail = s.str();
    }
    if (status == fmi2Warning) {
        receive(name, fmi2Warning, "logStatusWarning",
                std::string(function) + " returned "
                    + statusName(fmi2Warning, v3_) + detail);
        return;
    }
    std::string message = std::string(function) + " failed" + detail
        + " in FMU '" + fmuPath + "', instance '" + name + "' ("
        + statusName(status, v3_) + ")";
    if (!lastError_.empty())
        message += ": " + lastError_;
    throw Error(message);
}

void LocalInstance::setupExperiment(double startTime, bool stopTimeDefined,
                                    double stopTime)
{
    if (v3_) {
        startTime_ = startTime;
        stopTimeDefined_ = stopTimeDefined;
        stopTime_ = stopTime;
        return;
    }
    check(call("fmi2SetupExperiment", startTime, api().SetupExperiment,
               component_, fmi2False, 0, startTime,
               stopTimeDefined ? fmi2True : fmi2False, stopTime),
          "fmi2SetupExperiment", startTime);
}

void LocalInstance::enterInitializationMode()
{
    if (v3_)
        return enterInitializationMode3();
    check(call("fmi2EnterInitializationMode", time,
               api().EnterInitializationMode, component_),
          "fmi2EnterInitializationMode");
}

void LocalInstance::exitInitializationMode()
{
    if (v3_)
        return check(call("fmi3ExitInitializationMode", time,
                          api3().ExitInitializationMode, component_),
                     "fmi3ExitInitializationMode");
    check(call("fmi2ExitInitializationMode", time, api().ExitInitializationMode,
               component_),
          "fmi2ExitInitializationMode");
}

void LocalInstance::terminate()
{
    if (v3_)
        return check(call("fmi3Terminate", time, api3().Terminate, component_),
                     "fmi3Terminate", time);
    check(call("fmi2Terminate", time, api().Terminate, component_),
          "fmi2Terminate", time);
}

void LocalInstance::reset()
{
    if (v3_) {
        // instantiated again: the values set before initialization restart
        // from the start values
        check(call("fmi3Reset", time, api3().Reset, component_), "fmi3Reset");
        initializing_ = false;
        setBeforeInitialization_.clear();
        return;
    }
    check(call("fmi2Reset", time, api().Reset, component_), "fmi2Reset");
}

void LocalInstance::setReal(const std::vector<unsigned int>& vrs,
                            const std::vector<double>& values)
{
    if (v3_)
        return setReal3(vrs, values);
    check(call("fmi2SetReal", time, api().SetReal, component_, vrs.data(),
               vrs.size(), values.data()),
          "fmi2SetReal", time);
}

void LocalInstance::getReal(const std::vector<unsigned int>& vrs,
                            double* values)
{
    if (v3_)
        return getReal3(vrs, values);
    check(call("fmi2GetReal", time, api().GetReal, component_, vrs.data(),
               vrs.size(), values),
          "fmi2GetReal", time);
}

void LocalInstance::setInteger(const std::vector<unsigned int>& vrs,
                               const std::vector<int>& values)
{
    if (v3_)
        return setInteger3(vrs, values);
    check(call("fmi2SetInteger", time, api().SetInteger, component_, vrs.data(),
               vrs.size(), values.data()),
          "fmi2SetInteger", time);
}

std::vector<int> LocalInstance::getInteger(const std::vector<unsigned int>& vrs)
{
    if (v3_)
        return getInteger3(vrs);
    std::vector<int> values(vrs.size());
    check(call("fmi2GetInteger", time, api().GetInteger, component_, vrs.data(),
               vrs.size(), values.data()),
          "fmi2GetInteger", time);
    return values;
}

void LocalInstance::setBoolean(const std::vector<unsigned int>& vrs,
                               const std::vector<bool>& values)
{
    if (v3_)
        return setBoolean3(vrs, values);
    const std::vector<fmi2Boolean> raw(values.begin(), values.end());
    check(call("fmi2SetBoolean", time, api().SetBoolean, component_, vrs.data(),
               vrs.size(), raw.data()),
          "fmi2SetBoolean", time);
}

std::vector<bool>
LocalInstance::getBoolean(const std::vector<unsigned int>& vrs)
{
    if (v3_)
        return getBoolean3(vrs);
    std::vector<fmi2Boolean> raw(vrs.size());
    check(call("fmi2GetBoolean", time, api().GetBoolean, component_, vrs.data(),
               vrs.size(), raw.data()),
          "fmi2GetBoolean", time);
    return std::vector<bool>(raw.begin(), raw.end());
}

void LocalInstance::setString(const std::vector<unsigned int>& vrs,
                              const std::vector<std::string>& values)
{
    if (v3_)
        return setString3(vrs, values);
    std::vector<fmi2String> raw;
    for (const std::string& s : values)
        raw.push_back(s.c_str());
    check(call("fmi2SetString", time, api().SetString, component_, vrs.data(),
               vrs.size(), raw.data()),
          "fmi2SetString", time);
}

std::vector<std::string>
LocalInstance::getString(const std::vector<unsigned int>& vrs)
{
    if (v3_)
        return getString3(vrs);
    std::vector<fmi2String> raw(vrs.size(), nullptr);
    check(call("fmi2GetString", time, api().GetString, component_, vrs.data(),
               vrs.size(), raw.data()),
          "fmi2GetString", time);
    std::vector<std::string> values;
    for (const fmi2String s : raw)
        values.emplace_back(s ? s : "");
    return values;
}

Instance::StepResult
LocalInstance::doStep(double currentTime, double stepSize,
                      bool noSetFMUStatePriorToCurrentPoint, bool mayDiscard)
{
    if (v3_)
        return doStep3(currentTime, stepSize, noSetFMUStatePriorToCurrentPoint,
                       mayDiscard);
    const fmi2Status status = call(
        "fmi2DoStep", currentTime, api().DoStep, component_, currentTime,
        stepSize, noSetFMUStatePriorToCurrentPoint ? fmi2True : fmi2False);
    if (status != fmi2Discard || !mayDiscard) {
        check(status, "fmi2DoStep", currentTime);
        return Instance::StepResult::completed;
    }
    // Asking does not forget why the step was discarded
    const std::string reason = lastNotice_;
    fmi2Boolean terminated = fmi2False;
    check(call("fmi2GetBooleanStatus", currentTime, api().GetBooleanStatus,
               component_, fmi2Terminated, &terminated),
          "fmi2GetBooleanStatus(fmi2Terminated)", currentTime);
    lastNotice_ = reason;
    return terminated ? Instance::StepResult::terminated
                      : Instance::StepResult::discarded;
}

double LocalInstance::lastSuccessfulTime()
{
    if (v3_)
        return lastSuccessfulTime_;
    const std::string reason = lastNotice_;
    fmi2Real t = 0;
    check(call("fmi2GetRealStatus", time, api().GetRealStatus, component_,
               fmi2LastSuccessfulTime, &t),
          "fmi2GetRealStatus(fmi2LastSuccessfulTime)", time);
    lastNotice_ = reason;
    return t;
}

void* LocalInstance::getState(void* reuse)
{
    if (v3_)
        return getState3(reuse);
    fmi2FMUstate raw = reuse;
    check(call("fmi2GetFMUstate", time, api().GetFMUstate, component_, &raw),
          "fmi2GetFMUstate", time);
    return raw;
}

void LocalInstance::setState(void* state)
{
    if (v3_)
        return setState3(state);
    check(call("fmi2SetFMUstate", time, api().SetFMUstate, component_, state),
          "fmi2SetFMUstate", time);
}

void LocalInstance::freeState(void* state) noexcept
{
    if (v3_)
        return freeState3(state);
    call("fmi2FreeFMUstate", time, api().FreeFMUstate, component_, &state);
}

std::vector<char> LocalInstance::serializeState(void* state)
{
    if (v3_)
        return serializeState3(state);
    std::size_t size = 0;
    check(call("fmi2SerializedFMUstateSize", time, api().SerializedFMUstateSize,
               component_, state, &size),
          "fmi2SerializedFMUstateSize");
    std::vector<char> bytes(size);
    check(call("fmi2SerializeFMUstate", time, api().SerializeFMUstate,
               component_, state, bytes.data(), size),
          "fmi2SerializeFMUstate");
    return bytes;
}

void* LocalInstance::deserializeState(const std::vector<char>& bytes)
{
    if (v3_)
        return deserializeState3(bytes);
    fmi2FMUstate raw = nullptr;
    check(call("fmi2DeSerializeFMUstate", time, api().DeSerializeFMUstate,
               component_, bytes.data(), bytes.size(), &raw),
          "fmi2DeSerializeFMUstate");
    return raw;
}

} // namespace fmuImport

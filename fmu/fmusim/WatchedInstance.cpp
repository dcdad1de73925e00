#include "WatchedInstance.hpp"

#include <limits>

namespace fmusim {

WatchedInstance::WatchedInstance(const fmuImport::Fmu& fmu,
                                 const std::string& name,
                                 fmuImport::Logger logger, bool loggingOn)
    : site_(new CallSite {fmu.path(), name, fmu.unpackDirectory()})
{
    const FmuCall call(*site_, "fmi2Instantiate",
                       std::numeric_limits<double>::quiet_NaN());
    instance_ = std::make_unique<fmuImport::Instance>(
        fmu, name, std::move(logger), loggingOn);
}

WatchedInstance::~WatchedInstance()
{
    if (!instance_)
        return; // moved from
    const FmuCall call(*site_, "fmi2FreeInstance", instance_->time());
    instance_.reset();
}

void WatchedInstance::setupExperiment(double startTime, bool stopTimeDefined,
                                      double stopTime)
{
    const FmuCall call(*site_, "fmi2SetupExperiment", startTime);
    instance_->setupExperiment(startTime, stopTimeDefined, stopTime);
}

void WatchedInstance::enterInitializationMode()
{
    const FmuCall call(*site_, "fmi2EnterInitializationMode",
                       instance_->time());
    instance_->enterInitializationMode();
}

void WatchedInstance::exitInitializationMode()
{
    const FmuCall call(*site_, "fmi2ExitInitializationMode", instance_->time());
    instance_->exitInitializationMode();
}

void WatchedInstance::terminate()
{
    const FmuCall call(*site_, "fmi2Terminate", instance_->time());
    instance_->terminate();
}

void WatchedInstance::setReal(const std::vector<unsigned int>& vrs,
                              const std::vector<double>& values)
{
    const FmuCall call(*site_, "fmi2SetReal", instance_->time());
    instance_->setReal(vrs, values);
}

std::vector<double>
WatchedInstance::getReal(const std::vector<unsigned int>& vrs)
{
    const FmuCall call(*site_, "fmi2GetReal", instance_->time());
    return instance_->getReal(vrs);
}

void WatchedInstance::setInteger(const std::vector<unsigned int>& vrs,
                                 const std::vector<int>& values)
{
    const FmuCall call(*site_, "fmi2SetInteger", instance_->time());
    instance_->setInteger(vrs, values);
}

std::vector<int>
WatchedInstance::getInteger(const std::vector<unsigned int>& vrs)
{
    const FmuCall call(*site_, "fmi2GetInteger", instance_->time());
    return instance_->getInteger(vrs);
}

void WatchedInstance::setBoolean(const std::vector<unsigned int>& vrs,
                                 const std::vector<bool>& values)
{
    const FmuCall call(*site_, "fmi2SetBoolean", instance_->time());
    instance_->setBoolean(vrs, values);
}

std::vector<bool>
WatchedInstance::getBoolean(const std::vector<unsigned int>& vrs)
{
    const FmuCall call(*site_, "fmi2GetBoolean", instance_->time());
    return instance_->getBoolean(vrs);
}

void WatchedInstance::setString(const std::vector<unsigned int>& vrs,
                                const std::vector<std::string>& values)
{
    const FmuCall call(*site_, "fmi2SetString", instance_->time());
    instance_->setString(vrs, values);
}

std::vector<std::string>
WatchedInstance::getString(const std::vector<unsigned int>& vrs)
{
    const FmuCall call(*site_, "fmi2GetString", instance_->time());
    return instance_->getString(vrs);
}

void WatchedInstance::doStep(double currentTime, double stepSize)
{
    const FmuCall call(*site_, "fmi2DoStep", currentTime);
    instance_->doStep(currentTime, stepSize);
}

fmuImport::Instance::StepResult WatchedInstance::tryDoStep(double currentTime,
                                                           double stepSize)
{
    const FmuCall call(*site_, "fmi2DoStep", currentTime);
    return instance_->tryDoStep(currentTime, stepSize);
}

double WatchedInstance::lastSuccessfulTime()
{
    const FmuCall call(*site_, "fmi2GetRealStatus", instance_->time());
    return instance_->lastSuccessfulTime();
}

WatchedInstance::State WatchedInstance::getState()
{
    const FmuCall call(*site_, "fmi2GetFMUstate", instance_->time());
    return instance_->getState();
}

void WatchedInstance::setState(const State& state)
{
    const FmuCall call(*site_, "fmi2SetFMUstate", instance_->time());
    instance_->setState(state);
}

std::vector<char> WatchedInstance::serializeState(const State& state)
{
    const FmuCall call(*site_, "fmi2SerializeFMUstate", instance_->time());
    return instance_->serializeState(state);
}

WatchedInstance::State
WatchedInstance::deserializeState(const std::vector<char>& bytes)
{
    const FmuCall call(*site_, "fmi2DeSerializeFMUstate", instance_->time());
    return instance_->deserializeState(bytes);
}

} // namespace fmusim

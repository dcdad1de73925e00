#include "ChildInstance.hpp"
#include "LocalInstance.hpp"

#include <cmath>
#include <limits>

namespace fmuImport {

namespace {

void checkSizes(const std::vector<unsigned int>& vrs, std::size_t nValues,
                const char* function)
{
    if (vrs.size() != nValues)
        throw Error(std::string(function) + ": " + std::to_string(vrs.size())
                    + " value references but " + std::to_string(nValues)
                    + " values");
}

} // namespace

Instance::Instance(const Fmu& fmu, const std::string& instanceName,
                   Logger logger, bool loggingOn)
{
    if (!fmu.impl_)
        throw Error("Instance '" + instanceName + "': the FMU was moved from");
    if (fmu.options().isolation == Isolation::process)
        impl_ = std::make_shared<ChildInstance>(fmu.impl_, fmu.path(),
                                                instanceName, std::move(logger),
                                                loggingOn, fmu.options());
    else
        impl_ = std::make_shared<LocalInstance>(fmu.impl_, fmu.path(),
                                                instanceName, std::move(logger),
                                                loggingOn, fmu.options());
}

Instance::~Instance() = default;
Instance::Instance(Instance&&) noexcept = default;
Instance& Instance::operator=(Instance&&) noexcept = default;

const std::string& Instance::name() const
{
    return impl_->name;
}

const std::string& Instance::fmuPath() const
{
    return impl_->fmuPath;
}

void Instance::setupExperiment(double startTime, bool stopTimeDefined,
                               double stopTime)
{
    impl_->setupExperiment(startTime, stopTimeDefined, stopTime);
    impl_->time = startTime;
}

void Instance::enterInitializationMode()
{
    impl_->enterInitializationMode();
}

void Instance::exitInitializationMode()
{
    impl_->exitInitializationMode();
}

void Instance::terminate()
{
    impl_->terminate();
}

void Instance::reset()
{
    impl_->reset();
    impl_->time = 0;
}

void Instance::setReal(const std::vector<unsigned int>& vrs,
                       const std::vector<double>& values)
{
    checkSizes(vrs, values.size(), "fmi2SetReal");
    impl_->setReal(vrs, values);
}

std::vector<double> Instance::getReal(const std::vector<unsigned int>& vrs)
{
    std::vector<double> values(vrs.size());
    impl_->getReal(vrs, values.data());
    return values;
}

void Instance::getReal(const std::vector<unsigned int>& vrs,
                       std::vector<double>& values)
{
    values.resize(vrs.size());
    impl_->getReal(vrs, values.data());
}

void Instance::setInteger(const std::vector<unsigned int>& vrs,
                          const std::vector<int>& values)
{
    checkSizes(vrs, values.size(), "fmi2SetInteger");
    impl_->setInteger(vrs, values);
}

std::vector<int> Instance::getInteger(const std::vector<unsigned int>& vrs)
{
    return impl_->getInteger(vrs);
}

void Instance::setBoolean(const std::vector<unsigned int>& vrs,
                          const std::vector<bool>& values)
{
    checkSizes(vrs, values.size(), "fmi2SetBoolean");
    impl_->setBoolean(vrs, values);
}

std::vector<bool> Instance::getBoolean(const std::vector<unsigned int>& vrs)
{
    return impl_->getBoolean(vrs);
}

void Instance::setString(const std::vector<unsigned int>& vrs,
                         const std::vector<std::string>& values)
{
    checkSizes(vrs, values.size(), "fmi2SetString");
    impl_->setString(vrs, values);
}

std::vector<std::string>
Instance::getString(const std::vector<unsigned int>& vrs)
{
    return impl_->getString(vrs);
}

void Instance::doStep(double currentTime, double stepSize,
                      bool noSetFMUStatePriorToCurrentPoint)
{
    impl_->doStep(currentTime, stepSize, noSetFMUStatePriorToCurrentPoint,
                  false);
    impl_->time = currentTime + stepSize;
}

Instance::StepResult Instance::tryDoStep(double currentTime, double stepSize,
                                         bool noSetFMUStatePriorToCurrentPoint)
{
    const StepResult result = impl_->doStep(
        currentTime, stepSize, noSetFMUStatePriorToCurrentPoint, true);
    if (result == StepResult::completed)
        impl_->time = currentTime + stepSize;
    return result;
}

double Instance::lastSuccessfulTime()
{
    return impl_->lastSuccessfulTime();
}

std::string Instance::lastMessage() const
{
    return impl_->lastMessage();
}

Instance::State::State()
    : state_(nullptr), time_(std::numeric_limits<double>::quiet_NaN())
{
}

Instance::State::~State()
{
    if (owner_ && state_)
        owner_->freeState(state_);
}

Instance::State::State(State&& other) noexcept
    : owner_(std::move(other.owner_)), state_(other.state_), time_(other.time_)
{
    other.state_ = nullptr;
}

Instance::State& Instance::State::operator=(State&& other) noexcept
{
    if (this != &other) {
        State old(std::move(*this));
        owner_ = std::move(other.owner_);
        state_ = other.state_;
        time_ = other.time_;
        other.state_ = nullptr;
    }
    return *this;
}

bool Instance::State::valid() const
{
    return owner_ && state_;
}

Instance::State Instance::getState()
{
    State s;
    s.state_ = impl_->getState(nullptr);
    s.owner_ = impl_;
    s.time_ = impl_->time;
    return s;
}

void Instance::getState(State& state)
{
    if (!state.valid() || state.owner_ != impl_) {
        state = getState();
        return;
    }
    state.state_ = impl_->getState(state.state_);
    state.time_ = impl_->time;
}

void Instance::setState(const State& state)
{
    if (!state.valid() || state.owner_ != impl_)
        throw Error("fmi2SetFMUstate in FMU '" + impl_->fmuPath
                    + "', instance '" + impl_->name
                    + "': the state is empty or belongs to another instance");
    impl_->setState(state.state_);
    if (!std::isnan(state.time_))
        impl_->time = state.time_;
}

std::vector<char> Instance::serializeState(const State& state)
{
    if (!state.valid() || state.owner_ != impl_)
        throw Error("fmi2SerializeFMUstate in FMU '" + impl_->fmuPath
                    + "', instance '" + impl_->name
                    + "': the state is empty or belongs to another instance");
    return impl_->serializeState(state.state_);
}

Instance::State Instance::deserializeState(const std::vector<char>& bytes)
{
    State s;
    s.state_ = impl_->deserializeState(bytes);
    s.owner_ = impl_;
    return s;
}

double Instance::time() const
{
    return impl_->time;
}

} // namespace fmuImport

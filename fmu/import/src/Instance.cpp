#include "InstanceImpl.hpp"

#include <cmath>
#include <limits>
#include <sstream>

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
    impl_ = std::make_shared<Impl>(fmu.impl_, fmu.path(), instanceName,
                                   std::move(logger));
    Impl& d = *impl_;
    d.admit();
    const std::string resources = fmu.resourceLocation();
    d.beginCall();
    d.component
        = callFmu(d.api().Instantiate, instanceName.c_str(), fmi2CoSimulation,
                  d.fmu->description.guid.c_str(), resources.c_str(),
                  &d.callbacks, fmi2False, loggingOn ? fmi2True : fmi2False);
    if (!d.component) {
        std::string message = "fmi2Instantiate failed in FMU '" + d.fmuPath
            + "', instance '" + instanceName + "'";
        if (!d.lastError.empty())
            message += ": " + d.lastError;
        throw Error(message);
    }
}

Instance::~Instance() = default;
Instance::Instance(Instance&&) noexcept = default;
Instance& Instance::operator=(Instance&&) noexcept = default;

const std::string& Instance::name() const
{
    return impl_->name;
}

void Instance::setupExperiment(double startTime, bool stopTimeDefined,
                               double stopTime)
{
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().SetupExperiment, impl_->component,
                         fmi2False, 0, startTime,
                         stopTimeDefined ? fmi2True : fmi2False, stopTime),
                 "fmi2SetupExperiment", startTime);
    impl_->time = startTime;
}

void Instance::enterInitializationMode()
{
    impl_->beginCall();
    impl_->check(
        callFmu(impl_->api().EnterInitializationMode, impl_->component),
        "fmi2EnterInitializationMode");
}

void Instance::exitInitializationMode()
{
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().ExitInitializationMode, impl_->component),
                 "fmi2ExitInitializationMode");
}

void Instance::terminate()
{
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().Terminate, impl_->component),
                 "fmi2Terminate", impl_->time);
}

void Instance::reset()
{
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().Reset, impl_->component), "fmi2Reset");
    impl_->time = 0;
}

void Instance::setReal(const std::vector<unsigned int>& vrs,
                       const std::vector<double>& values)
{
    checkSizes(vrs, values.size(), "fmi2SetReal");
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().SetReal, impl_->component, vrs.data(),
                         vrs.size(), values.data()),
                 "fmi2SetReal", impl_->time);
}

std::vector<double> Instance::getReal(const std::vector<unsigned int>& vrs)
{
    std::vector<double> values(vrs.size());
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().GetReal, impl_->component, vrs.data(),
                         vrs.size(), values.data()),
                 "fmi2GetReal", impl_->time);
    return values;
}

void Instance::setInteger(const std::vector<unsigned int>& vrs,
                          const std::vector<int>& values)
{
    checkSizes(vrs, values.size(), "fmi2SetInteger");
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().SetInteger, impl_->component, vrs.data(),
                         vrs.size(), values.data()),
                 "fmi2SetInteger", impl_->time);
}

std::vector<int> Instance::getInteger(const std::vector<unsigned int>& vrs)
{
    std::vector<int> values(vrs.size());
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().GetInteger, impl_->component, vrs.data(),
                         vrs.size(), values.data()),
                 "fmi2GetInteger", impl_->time);
    return values;
}

void Instance::setBoolean(const std::vector<unsigned int>& vrs,
                          const std::vector<bool>& values)
{
    checkSizes(vrs, values.size(), "fmi2SetBoolean");
    const std::vector<fmi2Boolean> raw(values.begin(), values.end());
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().SetBoolean, impl_->component, vrs.data(),
                         vrs.size(), raw.data()),
                 "fmi2SetBoolean", impl_->time);
}

std::vector<bool> Instance::getBoolean(const std::vector<unsigned int>& vrs)
{
    std::vector<fmi2Boolean> raw(vrs.size());
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().GetBoolean, impl_->component, vrs.data(),
                         vrs.size(), raw.data()),
                 "fmi2GetBoolean", impl_->time);
    return std::vector<bool>(raw.begin(), raw.end());
}

void Instance::setString(const std::vector<unsigned int>& vrs,
                         const std::vector<std::string>& values)
{
    checkSizes(vrs, values.size(), "fmi2SetString");
    std::vector<fmi2String> raw;
    for (const std::string& s : values)
        raw.push_back(s.c_str());
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().SetString, impl_->component, vrs.data(),
                         vrs.size(), raw.data()),
                 "fmi2SetString", impl_->time);
}

std::vector<std::string>
Instance::getString(const std::vector<unsigned int>& vrs)
{
    std::vector<fmi2String> raw(vrs.size(), nullptr);
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().GetString, impl_->component, vrs.data(),
                         vrs.size(), raw.data()),
                 "fmi2GetString", impl_->time);
    std::vector<std::string> values;
    for (const fmi2String s : raw)
        values.emplace_back(s ? s : "");
    return values;
}

void Instance::doStep(double currentTime, double stepSize,
                      bool noSetFMUStatePriorToCurrentPoint)
{
    impl_->beginCall();
    impl_->check(
        callFmu(impl_->api().DoStep, impl_->component, currentTime, stepSize,
                noSetFMUStatePriorToCurrentPoint ? fmi2True : fmi2False),
        "fmi2DoStep", currentTime);
    impl_->time = currentTime + stepSize;
}

Instance::StepResult Instance::tryDoStep(double currentTime, double stepSize,
                                         bool noSetFMUStatePriorToCurrentPoint)
{
    impl_->beginCall();
    const fmi2Status status
        = callFmu(impl_->api().DoStep, impl_->component, currentTime, stepSize,
                  noSetFMUStatePriorToCurrentPoint ? fmi2True : fmi2False);
    if (status != fmi2Discard) {
        impl_->check(status, "fmi2DoStep", currentTime);
        impl_->time = currentTime + stepSize;
        return StepResult::completed;
    }
    // Asking does not forget why the step was discarded
    const std::string reason = impl_->lastNotice;
    fmi2Boolean terminated = fmi2False;
    impl_->check(callFmu(impl_->api().GetBooleanStatus, impl_->component,
                         fmi2Terminated, &terminated),
                 "fmi2GetBooleanStatus(fmi2Terminated)", currentTime);
    impl_->lastNotice = reason;
    return terminated ? StepResult::terminated : StepResult::discarded;
}

double Instance::lastSuccessfulTime()
{
    const std::string reason = impl_->lastNotice;
    fmi2Real time = 0;
    impl_->check(callFmu(impl_->api().GetRealStatus, impl_->component,
                         fmi2LastSuccessfulTime, &time),
                 "fmi2GetRealStatus(fmi2LastSuccessfulTime)", impl_->time);
    impl_->lastNotice = reason;
    return time;
}

std::string Instance::lastMessage() const
{
    return impl_->lastNotice;
}

Instance::State::State()
    : state_(nullptr), time_(std::numeric_limits<double>::quiet_NaN())
{
}

Instance::State::~State()
{
    if (owner_ && state_)
        callFmu(owner_->api().FreeFMUstate, owner_->component, &state_);
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
    fmi2FMUstate raw = nullptr;
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().GetFMUstate, impl_->component, &raw),
                 "fmi2GetFMUstate", impl_->time);
    s.owner_ = impl_;
    s.state_ = raw;
    s.time_ = impl_->time;
    return s;
}

void Instance::setState(const State& state)
{
    if (!state.valid() || state.owner_ != impl_)
        throw Error("fmi2SetFMUstate in FMU '" + impl_->fmuPath
                    + "', instance '" + impl_->name
                    + "': the state is empty or belongs to another instance");
    impl_->beginCall();
    impl_->check(
        callFmu(impl_->api().SetFMUstate, impl_->component, state.state_),
        "fmi2SetFMUstate", impl_->time);
    if (!std::isnan(state.time_))
        impl_->time = state.time_;
}

std::vector<char> Instance::serializeState(const State& state)
{
    if (!state.valid() || state.owner_ != impl_)
        throw Error("fmi2SerializeFMUstate in FMU '" + impl_->fmuPath
                    + "', instance '" + impl_->name
                    + "': the state is empty or belongs to another instance");
    std::size_t size = 0;
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().SerializedFMUstateSize, impl_->component,
                         state.state_, &size),
                 "fmi2SerializedFMUstateSize");
    std::vector<char> bytes(size);
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().SerializeFMUstate, impl_->component,
                         state.state_, bytes.data(), size),
                 "fmi2SerializeFMUstate");
    return bytes;
}

Instance::State Instance::deserializeState(const std::vector<char>& bytes)
{
    State s;
    fmi2FMUstate raw = nullptr;
    impl_->beginCall();
    impl_->check(callFmu(impl_->api().DeSerializeFMUstate, impl_->component,
                         bytes.data(), bytes.size(), &raw),
                 "fmi2DeSerializeFMUstate");
    s.owner_ = impl_;
    s.state_ = raw;
    return s;
}

double Instance::time() const
{
    return impl_->time;
}

} // namespace fmuImport

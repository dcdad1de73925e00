#include "FmuInstance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ModelDescription.hpp"
#include "common/ConnectorError.hpp"

namespace fmuExport {

FmuInstance::FmuInstance(std::unique_ptr<Model> model, std::string instanceName,
                         const fmi2CallbackFunctions& callbacks, bool loggingOn,
                         const char* fmiPrefix)
    : model_(std::move(model)), instanceName_(std::move(instanceName)),
      guid_(modelGuid(*model_)), callbacks_(callbacks), logCalls_(loggingOn),
      logRefusals_(loggingOn), fmiPrefix_(fmiPrefix)
{
    for (const ScalarVariable& v : model_->variables().variables()) {
        realAccess_.push_back(
            v.type != Type::Real                      ? RealAccess::none
                : v.causality == Causality::input     ? RealAccess::input
                : v.causality == Causality::parameter ? RealAccess::parameter
                : v.causality == Causality::output    ? RealAccess::output
                : v.causality == Causality::local     ? RealAccess::local
                                                      : RealAccess::none);
    }
    deferred_ = model_->deferredOutputs();
    for (std::size_t vr = 0; vr < realAccess_.size(); ++vr) {
        const RealAccess a = realAccess_[vr];
        realFlags_.push_back(static_cast<unsigned char>(
            (a != RealAccess::none ? realVariable : 0)
            | (a == RealAccess::input ? settableEachStep : 0)
            | (a == RealAccess::output || a == RealAccess::local ? computed : 0)
            | (vr - deferred_.first < deferred_.size ? deferredOutput : 0)));
    }
    startValues();
}

void FmuInstance::log(fmi2Status status, const char* category,
                      const std::string& message) const noexcept
{
    if (callbacks_.logger != nullptr) {
        callbacks_.logger(callbacks_.componentEnvironment,
                          instanceName_.c_str(), status, category, "%s",
                          message.c_str());
    }
}

void FmuInstance::logFailure(fmi2Status status, const char* function,
                             const char* message) const noexcept
{
    try {
        log(status, logCategoryError, std::string(function) + ": " + message);
    } catch (...) {
        log(status, logCategoryError, std::string());
    }
}

void FmuInstance::startValues()
{
    const std::vector<ScalarVariable>& variables
        = model_->variables().variables();
    values_.resize(variables.size());
    for (const ScalarVariable& v : variables) {
        values_[v.valueReference] = v.start;
    }
    time_ = 0.0;
    outputsValid_ = false;
    parametersApplied_ = false;
}

void FmuInstance::setDebugLogging(bool loggingOn, std::size_t nCategories,
                                  const fmi2String categories[])
{
    bool calls = nCategories == 0;
    bool refusals = nCategories == 0;
    for (std::size_t i = 0; i < nCategories; ++i) {
        const std::string category = categories[i] ? categories[i] : "";
        if (category == logCategoryCalls) {
            calls = true;
        } else if (category == logCategoryRefusal) {
            refusals = true;
        } else if (category != logCategoryError) {
            throw UsageError("unknown log category \"" + category
                             + "\" (known: logStatusError, logCalls, "
                               "refusedParameter)");
        }
    }
    if (calls) {
        logCalls_ = loggingOn;
    }
    if (refusals) {
        logRefusals_ = loggingOn;
    }
}

void FmuInstance::setupExperiment(double startTime)
{
    if (!std::isfinite(startTime)) {
        throw UsageError("startTime is not finite");
    }
    time_ = startTime;
}

void FmuInstance::enterInitializationMode()
{
    state_ = initializationMode;
}

void FmuInstance::applyParameters(const double* values)
{
    if (parametersApplied_) {
        return;
    }
    try {
        model_->setParameters(values);
    } catch (const connectors::ParameterError& e) {
        if (logRefusals_) {
            log(fmi2Error, logCategoryRefusal,
                e.parameter() + " " + connectors::refusalName(e.code()) + ": "
                    + e.what());
        }
        throw;
    }
    parametersApplied_ = true;
}

bool FmuInstance::sameParameters(const std::vector<double>& values) const
{
    for (std::size_t vr = 0; vr < realAccess_.size(); ++vr) {
        if (realAccess_[vr] == RealAccess::parameter
            && values[vr] != values_[vr]) {
            return false;
        }
    }
    return true;
}

void FmuInstance::exitInitializationMode()
{
    applyParameters(values_.data());
    model_->initializeState(values_.data(), time_);
    state_ = stepComplete;
}

void FmuInstance::terminate()
{
    state_ = terminated;
}

void FmuInstance::reset()
{
    startValues();
    model_->setInternalState(values_.data(), {});
    state_ = instantiated;
}

std::string FmuInstance::describe(fmi2ValueReference vr) const
{
    if (names_) {
        return names_(vr);
    }
    return model_->variables().variables()[vr].name + " (value reference "
        + std::to_string(vr) + ")";
}

const ScalarVariable& FmuInstance::variable(fmi2ValueReference vr,
                                            Type type) const
{
    if (vr >= values_.size()) {
        throw UsageError("value reference " + std::to_string(vr)
                         + " is not a variable of "
                         + model_->identity().modelIdentifier + " (0 to "
                         + std::to_string(values_.size() - 1) + ")");
    }
    const ScalarVariable& v = model_->variables().variables()[vr];
    if (v.type != type) {
        throw UsageError("value reference " + std::to_string(vr) + " (" + v.name
                         + ") is not of type "
                         + (type == Type::Real ? "Real" : "Boolean"));
    }
    return v;
}

void FmuInstance::computeOutputs()
{
    applyParameters(values_.data());
    model_->computeOutputs(values_.data());
    outputsValid_ = true;
    deferredValid_ = true;
}

void FmuInstance::getReal(const fmi2ValueReference vr[], std::size_t n,
                          fmi2Real value[])
{
    // In one pass through the references' flags without a branch per value
    // (a connector's outputs every step); a reference to no Real variable
    // is named by realAccess after
    unsigned char any = 0, every = realVariable;
    const std::size_t size = realFlags_.size();
    const unsigned char* const flags = realFlags_.data();
    for (std::size_t i = 0; i < n; ++i) {
        const unsigned char f = vr[i] < size ? flags[vr[i]] : 0;
        any |= f;
        every &= f;
    }
    for (std::size_t i = 0; every == 0 && i < n; ++i) {
        realAccess(vr[i]);
    }
    const bool needsOutputs = (any & computed) != 0;
    const bool needsDeferred = (any & deferredOutput) != 0;
    if (needsOutputs && !outputsValid_) {
        computeOutputs();
    }
    if (needsDeferred && !deferredValid_) {
        model_->completeOutputs(values_.data());
        deferredValid_ = true;
    }
    const double* values = values_.data();
    for (std::size_t i = 0; i < n; ++i) {
        value[i] = values[vr[i]];
    }
}

void FmuInstance::setReal(const fmi2ValueReference vr[], std::size_t n,
                          const fmi2Real value[])
{
    // Every value reference is checked before any value is set; the
    // values are then copied in a loop that writes nothing else. Inputs
    // alone (a connector's every step) are told in one pass without a
    // branch per value; otherwise each is checked and the first that
    // cannot be set is named
    unsigned char every = settableEachStep;
    const std::size_t size = realFlags_.size();
    const unsigned char* const flags = realFlags_.data();
    for (std::size_t i = 0; i < n; ++i) {
        every &= vr[i] < size ? flags[vr[i]] : 0;
    }
    const bool inputsOnly = every != 0;
    bool parameters = false;
    for (std::size_t i = 0; !inputsOnly && i < n; ++i) {
        const RealAccess access = realAccess(vr[i]);
        if (access == RealAccess::input) {
            continue;
        }
        if (access == RealAccess::output) {
            throw UsageError("variable " + describe(vr[i])
                             + " is an output and cannot be set");
        }
        if (access == RealAccess::local) {
            throw UsageError("variable " + describe(vr[i])
                             + " is calculated by the FMU and cannot be set");
        }
        if (access == RealAccess::parameter
            && (state_ & (instantiated | initializationMode)) == 0) {
            throw UsageError("parameter " + describe(vr[i])
                             + " is fixed: set it before " + fmiPrefix_
                             + "ExitInitializationMode");
        }
        parameters = parameters || access == RealAccess::parameter;
    }
    double* values = values_.data();
    for (std::size_t i = 0; i < n; ++i) {
        values[vr[i]] = value[i];
    }
    parametersApplied_ = parametersApplied_ && !parameters;
    outputsValid_ = outputsValid_ && n == 0;
}

void FmuInstance::getBoolean(const fmi2ValueReference vr[], std::size_t n,
                             fmi2Boolean value[])
{
    for (std::size_t i = 0; i < n; ++i) {
        variable(vr[i], Type::Boolean);
    }
    for (std::size_t i = 0; i < n; ++i) {
        value[i] = values_[vr[i]] != 0.0 ? fmi2True : fmi2False;
    }
}

void FmuInstance::setBoolean(const fmi2ValueReference vr[], std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i) {
        throw UsageError("variable " + variable(vr[i], Type::Boolean).name
                         + " is a constant and cannot be set");
    }
}

void FmuInstance::rejectValueReferences(const char* type,
                                        const fmi2ValueReference vr[],
                                        std::size_t n) const
{
    if (n > 0) {
        // The types' names of the interface in use
        const bool fmi3 = std::string(fmiPrefix_) == "fmi3";
        throw UsageError(
            "value reference " + std::to_string(vr[0]) + " is not of type "
            + type + ": " + model_->identity().modelIdentifier + " has only "
            + (fmi3 ? "Float64" : "Real") + " and Boolean variables");
    }
}

void FmuInstance::doStep(double currentCommunicationPoint,
                         double communicationStepSize)
{
    const double t = currentCommunicationPoint;
    const double h = communicationStepSize;
    if (!std::isfinite(h) || h <= 0.0) {
        throw UsageError("communicationStepSize = " + formatDouble(h)
                         + " must be finite and > 0");
    }
    if (!std::isfinite(t)
        || std::abs(t - time_) > 1e-9 * std::max(1.0, std::abs(time_))) {
        throw UsageError("currentCommunicationPoint = " + formatDouble(t)
                         + " does not match the FMU time "
                         + formatDouble(time_));
    }
    applyParameters(values_.data());
    model_->doStep(values_.data(), t, h);
    outputsValid_ = true;
    deferredValid_ = deferred_.size == 0;
    time_ = t + h;
}

SavedState& FmuInstance::ownedState(fmi2FMUstate state)
{
    for (const std::unique_ptr<SavedState>& s : savedStates_) {
        if (s.get() == state) {
            return *s;
        }
    }
    throw UsageError("FMU state handle was not created by this instance or "
                     "was already freed");
}

fmi2FMUstate FmuInstance::getState(fmi2FMUstate reuse)
{
    SavedState* target = nullptr;
    if (reuse != nullptr) {
        target = &ownedState(reuse);
    } else {
        savedStates_.push_back(std::make_unique<SavedState>());
        target = savedStates_.back().get();
    }
    target->state = state_;
    target->time = time_;
    target->outputsValid = outputsValid_;
    target->values = values_;
    model_->saveInternalState(target->internal);
    return target;
}

void FmuInstance::setState(fmi2FMUstate state)
{
    const SavedState& saved = ownedState(state);
    const bool sameParameters = this->sameParameters(saved.values);
    parametersApplied_ = parametersApplied_ && sameParameters;
    try {
        if (!saved.internal.empty()) {
            applyParameters(saved.values.data());
        }
        model_->setInternalState(saved.values.data(), saved.internal);
    } catch (const std::invalid_argument& e) {
        // values_ stays: what was built for the saved parameters is not
        // for them
        parametersApplied_ = parametersApplied_ && sameParameters;
        throw UsageError(e.what());
    }
    values_ = saved.values;
    time_ = saved.time;
    outputsValid_ = saved.outputsValid;
    // computed again from the restored state when read
    deferredValid_ = deferred_.size == 0;
    state_ = saved.state;
}

void FmuInstance::freeState(fmi2FMUstate state)
{
    if (state == nullptr) {
        return;
    }
    ownedState(state);
    savedStates_.erase(
        std::find_if(savedStates_.begin(), savedStates_.end(),
                     [state](const std::unique_ptr<SavedState>& s) {
                         return s.get() == state;
                     }));
}

std::size_t FmuInstance::serializedStateSize(fmi2FMUstate state)
{
    const SavedState& saved = ownedState(state);
    return serializedSize(saved.values.size(), saved.internal.size());
}

void FmuInstance::serializeState(fmi2FMUstate state, fmi2Byte buffer[],
                                 std::size_t size)
{
    if (buffer == nullptr) {
        throw UsageError("serializedState buffer is NULL");
    }
    fmuExport::serializeState(ownedState(state), guid_, buffer, size);
}

fmi2FMUstate FmuInstance::deserializeState(const fmi2Byte bytes[],
                                           std::size_t size, fmi2FMUstate reuse)
{
    SavedState state
        = fmuExport::deserializeState(bytes, size, guid_, values_.size());
    if (reuse != nullptr) {
        ownedState(reuse) = std::move(state);
        return reuse;
    }
    savedStates_.push_back(std::make_unique<SavedState>(std::move(state)));
    return savedStates_.back().get();
}

} // namespace fmuExport

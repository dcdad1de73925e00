// One FMU instance: value array, FMI 2.0 co-simulation state machine,
// logging, saved states. Every fmi2 entry point runs its body through
// call(), which checks the state and turns exceptions into status codes.
#ifndef FMU_EXPORT_FMUINSTANCE_HPP
#define FMU_EXPORT_FMUINSTANCE_HPP

#include <functional>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "FmuState.hpp"
#include "Model.hpp"
#include "fmi2FunctionTypes.h"

namespace fmuExport {

class FmuInstance {
public:
    //- `fmiPrefix` ("fmi2", "fmi3") names the FMI functions in messages
    FmuInstance(std::unique_ptr<Model> model, std::string instanceName,
                const fmi2CallbackFunctions& callbacks, bool loggingOn,
                const char* fmiPrefix = "fmi2");

    FmuInstance(const FmuInstance&) = delete;
    FmuInstance& operator=(const FmuInstance&) = delete;

    //- Runs body() if the instance is in one of the `allowed` states.
    //  UsageError: fmi2Error, state unchanged. bad_alloc: fmi2Fatal, state
    //  fatal. Any other exception: fmi2Error, state error. Every failure is
    //  logged as "<function>: <message>" in category logStatusError.
    template <class Body>
    fmi2Status call(const char* function, unsigned allowed,
                    Body&& body) noexcept;

    //- Sends a message to the environment's logger; never throws
    void log(fmi2Status status, const char* category,
             const std::string& message) const noexcept;

    void setDebugLogging(bool loggingOn, std::size_t nCategories,
                         const fmi2String categories[]);
    void setupExperiment(double startTime);
    void enterInitializationMode();
    void exitInitializationMode();
    void terminate();
    void reset();

    //- How messages name the variable of an element's value reference
    //  (its name and value reference in the interface the importer uses):
    //  by default the element's own, as FMI 2.0 declares it
    using VariableNames = std::function<std::string(fmi2ValueReference)>;
    void setVariableNames(VariableNames names) { names_ = std::move(names); }

    void getReal(const fmi2ValueReference vr[], std::size_t n,
                 fmi2Real value[]);
    void setReal(const fmi2ValueReference vr[], std::size_t n,
                 const fmi2Real value[]);
    void getBoolean(const fmi2ValueReference vr[], std::size_t n,
                    fmi2Boolean value[]);
    //- Booleans are constants: any value reference is refused
    void setBoolean(const fmi2ValueReference vr[], std::size_t n);
    //- Integer and String: the models declare none
    void rejectValueReferences(const char* type, const fmi2ValueReference vr[],
                               std::size_t n) const;

    void doStep(double currentCommunicationPoint, double communicationStepSize);
    double time() const { return time_; }

    //- fmi2GetFMUstate: a new state, or `reuse` overwritten
    fmi2FMUstate getState(fmi2FMUstate reuse);
    void setState(fmi2FMUstate state);
    void freeState(fmi2FMUstate state);
    std::size_t serializedStateSize(fmi2FMUstate state);
    void serializeState(fmi2FMUstate state, fmi2Byte buffer[],
                        std::size_t size);
    fmi2FMUstate deserializeState(const fmi2Byte bytes[], std::size_t size,
                                  fmi2FMUstate reuse);

private:
    //- Logs "<function>: <message>" in category logStatusError
    void logFailure(fmi2Status status, const char* function,
                    const char* message) const noexcept;
    //- The saved state behind a handle; UsageError if not one of ours
    SavedState& ownedState(fmi2FMUstate state);
    void startValues();
    //- The variable behind vr; UsageError if none or not of type `type`
    const ScalarVariable& variable(fmi2ValueReference vr, Type type) const;

    //- How a Real value reference may be used, checked on every access
    enum class RealAccess : unsigned char {
        input,
        parameter,
        output,
        local,
        none
    };

    //- Access of a Real variable; UsageError (from variable()) otherwise
    RealAccess realAccess(fmi2ValueReference vr) const
    {
        if (vr >= realAccess_.size() || realAccess_[vr] == RealAccess::none) {
            variable(vr, Type::Real);
        }
        return realAccess_[vr];
    }
    //- Model::setParameters for the parameters in `values`, unless done for
    //  the current ones already; a refusal is logged in category
    //  refusedParameter (when enabled) before it is thrown on
    void applyParameters(const double* values);
    //- Whether the parameters in `values` are those in values_
    bool sameParameters(const std::vector<double>& values) const;
    void computeOutputs();
    //- "<name> (value reference <vr>)" of vr's variable (names_)
    std::string describe(fmi2ValueReference vr) const;

    std::unique_ptr<Model> model_;
    std::string instanceName_;
    std::string guid_;
    fmi2CallbackFunctions callbacks_;
    bool logCalls_;
    bool logRefusals_;
    const char* fmiPrefix_;
    VariableNames names_;
    ModelState state_ = instantiated;
    double time_ = 0.0;
    bool outputsValid_ = false;
    //- Whether the model's deferred outputs (Model::deferredOutputs) are
    //  those of the current inputs and state, and that block
    bool deferredValid_ = false;
    Block deferred_;
    //- Whether the model's setParameters ran for the parameters in values_
    bool parametersApplied_ = false;
    std::vector<double> values_;
    //- Per value reference: the RealAccess of its variable
    std::vector<RealAccess> realAccess_;
    //- The same as flags that fmi2GetReal and fmi2SetReal combine in one
    //  pass over the references they are given
    enum RealFlag : unsigned char {
        realVariable = 1,
        settableEachStep = 2, // an input
        computed = 4, // an output or local
        deferredOutput = 8 // in Model::deferredOutputs
    };
    std::vector<unsigned char> realFlags_;
    std::vector<std::unique_ptr<SavedState>> savedStates_;
};

template <class Body>
fmi2Status FmuInstance::call(const char* function, unsigned allowed,
                             Body&& body) noexcept
{
    try {
        if (logCalls_) {
            log(fmi2OK, "logCalls", function);
        }
        if ((state_ & allowed) == 0) {
            throw UsageError(std::string("not allowed in state ")
                             + stateName(state_) + " (allowed in "
                             + stateNames(allowed) + ")");
        }
        body();
        return fmi2OK;
    } catch (const UsageError& e) {
        logFailure(fmi2Error, function, e.what());
        return fmi2Error;
    } catch (const std::bad_alloc&) {
        state_ = fatal;
        logFailure(fmi2Fatal, function, "out of memory");
        return fmi2Fatal;
    } catch (const std::exception& e) {
        state_ = error;
        logFailure(fmi2Error, function, e.what());
        return fmi2Error;
    } catch (...) {
        state_ = error;
        logFailure(fmi2Error, function, "unknown exception");
        return fmi2Error;
    }
}

} // namespace fmuExport

#endif

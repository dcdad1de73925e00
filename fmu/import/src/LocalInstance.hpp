// An instance in this process: the fmi2Component (FMI 2.0) or fmi3Instance
// (FMI 3.0), its callbacks, the checking of every call, and the mark of the
// call in progress (CallReport) that names it when it crashes, hangs or
// exits. One class for both versions: each function switches on the FMU's
// version, the FMI 3.0 calls being in LocalInstance3.cpp.
#ifndef FMUIMPORT_LOCALINSTANCE_HPP
#define FMUIMPORT_LOCALINSTANCE_HPP

#include "CallReport.hpp"
#include "ElementPlan.hpp"
#include "FpTraps.hpp"
#include "InstanceImpl.hpp"

#include <limits>
#include <string>

namespace fmuImport {

// Where an instance's messages go without a logger: "[name] fmi2Warning
// category: message" on standard error ("fmi3Warning" with fmi3).
void logToStderr(const std::string& instanceName, int status,
                 const std::string& category, const std::string& message,
                 bool fmi3 = false);

class LocalInstance : public Instance::Impl {
public:
    // fmi2Instantiate; throws Error as Instance's constructor documents.
    LocalInstance(std::shared_ptr<Fmu::Impl> fmu, const std::string& fmuPath,
                  const std::string& name, Logger logger, bool loggingOn,
                  const FmuOptions& options);
    ~LocalInstance() override; // fmi2FreeInstance

    void setupExperiment(double startTime, bool stopTimeDefined,
                         double stopTime) override;
    void enterInitializationMode() override;
    void exitInitializationMode() override;
    void terminate() override;
    void reset() override;
    void setReal(const std::vector<unsigned int>& vrs,
                 const std::vector<double>& values) override;
    void getReal(const std::vector<unsigned int>& vrs, double* values) override;
    void setInteger(const std::vector<unsigned int>& vrs,
                    const std::vector<int>& values) override;
    std::vector<int> getInteger(const std::vector<unsigned int>& vrs) override;
    void setBoolean(const std::vector<unsigned int>& vrs,
                    const std::vector<bool>& values) override;
    std::vector<bool> getBoolean(const std::vector<unsigned int>& vrs) override;
    void setString(const std::vector<unsigned int>& vrs,
                   const std::vector<std::string>& values) override;
    std::vector<std::string>
    getString(const std::vector<unsigned int>& vrs) override;
    Instance::StepResult doStep(double currentTime, double stepSize,
                                bool noSetFMUStatePriorToCurrentPoint,
                                bool mayDiscard) override;
    double lastSuccessfulTime() override;
    std::string lastMessage() const override { return lastNotice_; }
    void* getState(void* reuse) override;
    void setState(void* state) override;
    void freeState(void* state) noexcept override;
    std::vector<char> serializeState(void* state) override;
    void* deserializeState(const std::vector<char>& bytes) override;

    // Receives a formatted message from the FMU (or from check).
    void receive(const std::string& instanceName, int status,
                 const std::string& category, const std::string& message);

private:
    const Fmi2Api& api() const { return fmu->library().api(); }
    const Fmi3Api& api3() const { return fmu->library().api3(); }

    // FMI 3.0 (LocalInstance3.cpp): the same functions through fmi3
    void instantiate3(bool loggingOn);
    void enterInitializationMode3();
    void setReal3(const std::vector<unsigned int>& vrs,
                  const std::vector<double>& values);
    void getReal3(const std::vector<unsigned int>& vrs, double* values);
    void setInteger3(const std::vector<unsigned int>& vrs,
                     const std::vector<int>& values);
    std::vector<int> getInteger3(const std::vector<unsigned int>& vrs);
    void setBoolean3(const std::vector<unsigned int>& vrs,
                     const std::vector<bool>& values);
    std::vector<bool> getBoolean3(const std::vector<unsigned int>& vrs);
    void setString3(const std::vector<unsigned int>& vrs,
                    const std::vector<std::string>& values);
    std::vector<std::string> getString3(const std::vector<unsigned int>& vrs);
    Instance::StepResult doStep3(double currentTime, double stepSize,
                                 bool noSetFMUStatePriorToCurrentPoint,
                                 bool mayDiscard);
    void* getState3(void* reuse);
    void setState3(void* state);
    void freeState3(void* state) noexcept;
    std::vector<char> serializeState3(void* state);
    void* deserializeState3(const std::vector<char>& bytes);
    // One group's values (ElementPlan): integers of any width, and String
    // or Binary (as hexadecimal text)
    void readIntegers(const ElementPlan::Group& g,
                      std::vector<long double>& out);
    void writeIntegers(const ElementPlan::Group& g,
                       const std::vector<long double>& in);
    void readTexts(const ElementPlan::Group& g, std::vector<std::string>& out);

    // Where the elements of an FMI 3.0 call's value references are: the
    // arrays (whole, each once, by element type) that a fmi3Get or fmi3Set
    // call passes, and for every element asked for, its array's group and
    // its position in that group's values (ElementPlan.hpp).
    const ElementPlan& plan(const std::vector<unsigned int>& vrs, Type type,
                            const char* function);

    // Counts this instance among the live instances of its binary; throws
    // Error if the FMU declares canBeInstantiatedOnlyOncePerProcess and
    // another one is alive. Call before fmi2Instantiate.
    void admit();

    // Calls the FMU function f with args: forgets the error text of earlier
    // calls, marks the call (function, the time t) and masks the host's
    // floating-point traps for its length.
    template <class F, class... Args>
    auto call(const char* function, double t, F* f, Args&&... args)
    {
        lastError_.clear();
        lastNotice_.clear();
        const MarkedCall mark(site_, function, t);
        return callFmu(f, static_cast<Args&&>(args)...);
    }

    // Throws Error for fmi2Error, fmi2Fatal, fmi2Discard and fmi2Pending,
    // naming function, the time (" at t = ...", when t is not NaN), the
    // FMU and the instance; reports fmi2Warning to the logger. Formatting
    // happens only on failure: calls are on hot paths.
    // FMI 3.0 statuses have the values of FMI 2.0's and are named fmi3OK, ...
    void check(fmi2Status status, const char* function,
               double t = std::numeric_limits<double>::quiet_NaN());
    void check(fmi3Status status, const char* function,
               double t = std::numeric_limits<double>::quiet_NaN())
    {
        if (status != fmi3OK)
            check(static_cast<fmi2Status>(status), function, t);
    }

    const bool v3_; // an FMI 3.0 FMU
    Logger logger_;
    CallSite site_; // what reports of a lost call name
    fmi2CallbackFunctions callbacks_; // the FMU may keep a pointer to it
    fmi2Component component_ = nullptr;
    std::string lastError_; // last error the FMU logged during the current call
    std::string lastNotice_; // last message at fmi2Warning or above, the same
    bool admitted_ = false; // counted in fmu->liveInstances

    // FMI 3.0: what setupExperiment gave, for fmi3EnterInitializationMode;
    // the last step's lastSuccessfulTime; the plans made so far
    double startTime_ = 0, stopTime_ = 0;
    bool stopTimeDefined_ = false;
    double lastSuccessfulTime_ = 0;
    ElementPlans plans_;
    // In initialization mode or later (fmi3Get allowed); before it, the
    // Real arrays set in part, whole, for the next part set
    bool initializing_ = false;
    std::unordered_map<unsigned int, std::vector<double>>
        setBeforeInitialization_;
};

} // namespace fmuImport

#endif

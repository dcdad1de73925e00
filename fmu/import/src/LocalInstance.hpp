// An instance in this process: the fmi2Component, its callbacks, the
// checking of every fmi2 call, and the mark of the call in progress
// (CallReport) that names it when it crashes, hangs or exits.
#ifndef FMUIMPORT_LOCALINSTANCE_HPP
#define FMUIMPORT_LOCALINSTANCE_HPP

#include "CallReport.hpp"
#include "FpTraps.hpp"
#include "InstanceImpl.hpp"

#include <limits>
#include <string>

namespace fmuImport {

// Where an instance's messages go without a logger: "[name] fmi2Warning
// category: message" on standard error.
void logToStderr(const std::string& instanceName, int status,
                 const std::string& category, const std::string& message);

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
    std::vector<double> getReal(const std::vector<unsigned int>& vrs) override;
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
    void* getState() override;
    void setState(void* state) override;
    void freeState(void* state) noexcept override;
    std::vector<char> serializeState(void* state) override;
    void* deserializeState(const std::vector<char>& bytes) override;

    // Receives a formatted message from the FMU (or from check).
    void receive(const std::string& instanceName, int status,
                 const std::string& category, const std::string& message);

private:
    const Fmi2Api& api() const { return fmu->library().api(); }

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
    void check(fmi2Status status, const char* function,
               double t = std::numeric_limits<double>::quiet_NaN());

    Logger logger_;
    CallSite site_; // what reports of a lost call name
    fmi2CallbackFunctions callbacks_; // the FMU may keep a pointer to it
    fmi2Component component_ = nullptr;
    std::string lastError_; // last error the FMU logged during the current call
    std::string lastNotice_; // last message at fmi2Warning or above, the same
    bool admitted_ = false; // counted in fmu->liveInstances
};

} // namespace fmuImport

#endif

// An fmuImport::Instance whose every call into the FMU is announced to the
// watchdog and the crash report (Watchdog.hpp): the same calls, each wrapped
// in an FmuCall naming its fmi2 function and communication point. fmusim
// drives FMUs only through this class.
#ifndef FMUSIM_WATCHEDINSTANCE_HPP
#define FMUSIM_WATCHEDINSTANCE_HPP

#include "Watchdog.hpp"

#include "fmuImport/fmuImport.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fmusim {

class WatchedInstance {
public:
    using State = fmuImport::Instance::State;

    // fmi2Instantiate; throws fmuImport::Error as fmuImport::Instance does.
    WatchedInstance(const fmuImport::Fmu& fmu, const std::string& name,
                    fmuImport::Logger logger, bool loggingOn);
    ~WatchedInstance(); // fmi2FreeInstance (unless a saved State still holds the instance)
    WatchedInstance(WatchedInstance&&) noexcept = default;
    WatchedInstance& operator=(WatchedInstance&&) noexcept = default;

    const std::string& name() const { return site_->instanceName; }
    const std::string& fmuPath() const { return site_->fmuPath; }
    double time() const { return instance_->time(); }

    void setupExperiment(double startTime, bool stopTimeDefined = false,
                         double stopTime = 0);
    void enterInitializationMode();
    void exitInitializationMode();
    void terminate();

    void setReal(const std::vector<unsigned int>& vrs,
                 const std::vector<double>& values);
    std::vector<double> getReal(const std::vector<unsigned int>& vrs);
    void setInteger(const std::vector<unsigned int>& vrs,
                    const std::vector<int>& values);
    std::vector<int> getInteger(const std::vector<unsigned int>& vrs);
    void setBoolean(const std::vector<unsigned int>& vrs,
                    const std::vector<bool>& values);
    std::vector<bool> getBoolean(const std::vector<unsigned int>& vrs);
    void setString(const std::vector<unsigned int>& vrs,
                   const std::vector<std::string>& values);
    std::vector<std::string> getString(const std::vector<unsigned int>& vrs);

    void doStep(double currentTime, double stepSize);
    // fmuImport::Instance::tryDoStep: a discarded or terminated step is a
    // result, not an error
    fmuImport::Instance::StepResult tryDoStep(double currentTime,
                                              double stepSize);
    double lastSuccessfulTime();
    std::string lastMessage() const { return instance_->lastMessage(); }

    State getState();
    void setState(const State& state);
    std::vector<char> serializeState(const State& state);
    State deserializeState(const std::vector<char>& bytes);

private:
    // On the heap, so that a call's site stays put when the instance moves.
    std::unique_ptr<CallSite> site_;
    std::unique_ptr<fmuImport::Instance> instance_;
};

} // namespace fmusim

#endif

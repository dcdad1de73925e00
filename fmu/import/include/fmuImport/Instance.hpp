// fmuImport: one instance of an FMU (Instance), its calls, saved states and
// log messages (Logger).
// Part of the importer's public interface (fmuImport.hpp includes every
// part), C++11 like the rest of it.
#ifndef FMUIMPORT_INSTANCE_HPP
#define FMUIMPORT_INSTANCE_HPP

#include "fmuImport/Fmu.hpp"
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fmuImport {

// Receives the FMU's log messages, formatted; status is an fmi2Status value
// (0 OK, 1 Warning, 2 Discard, 3 Error, 4 Fatal, 5 Pending).
using Logger = std::function<void(const std::string& instanceName, int status,
                                  const std::string& category,
                                  const std::string& message)>;

// One co-simulation fmi2Component (FMI 2.0) or fmi3Instance (FMI 3.0,
// instantiated with eventModeUsed and earlyReturnAllowed false: the FMU
// handles its events inside fmi3DoStep), in this process or in a child
// process (the Fmu's FmuOptions). The functions below are named after FMI
// 2.0's; for an FMI 3.0 FMU setupExperiment keeps the times for
// fmi3EnterInitializationMode, getReal and setReal call fmi3GetFloat64 and
// fmi3SetFloat64 (and Float32) on whole arrays, getInteger and setInteger
// the fmi3 integer functions, and a step that asks for event handling or
// returns early throws Error naming it. Every call is checked: fmi2Error,
// fmi2Fatal, fmi2Discard or fmi2Pending (fmi3Error, ...) throw Error naming the FMU, the
// instance and the function, with the last error the FMU logged appended;
// fmi2Warning is reported to the logger and the call goes on. A call that
// does not come back throws LostCall (Isolation::process) or ends the
// process (Isolation::none). Calls come from one thread at a time.
class Instance {
public:
    // The FMU's log messages go to logger, or to stderr when it is empty.
    // Throws Error if the FMU declares canBeInstantiatedOnlyOncePerProcess
    // and another instance of its binary is alive.
    Instance(const Fmu& fmu, const std::string& instanceName,
             Logger logger = Logger(), bool loggingOn = false);
    ~Instance();
    Instance(Instance&&) noexcept;
    Instance& operator=(Instance&&) noexcept;
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    const std::string& name() const;
    const std::string& fmuPath() const; // as the Fmu names it

    void setupExperiment(double startTime, bool stopTimeDefined = false,
                         double stopTime = 0);
    void enterInitializationMode();
    void exitInitializationMode();
    void terminate();
    void reset();

    void setReal(const std::vector<unsigned int>& vrs,
                 const std::vector<double>& values);
    std::vector<double> getReal(const std::vector<unsigned int>& vrs);
    // The same into values, resized to vrs.size(): a caller that reads the
    // same values every step allocates nothing after the first.
    void getReal(const std::vector<unsigned int>& vrs,
                 std::vector<double>& values);
    void setInteger(const std::vector<unsigned int>& vrs,
                    const std::vector<int>& values);
    std::vector<int> getInteger(const std::vector<unsigned int>& vrs);
    void setBoolean(const std::vector<unsigned int>& vrs,
                    const std::vector<bool>& values);
    std::vector<bool> getBoolean(const std::vector<unsigned int>& vrs);
    void setString(const std::vector<unsigned int>& vrs,
                   const std::vector<std::string>& values);
    std::vector<std::string> getString(const std::vector<unsigned int>& vrs);

    // Advances from currentTime to currentTime + stepSize; fmi2Discard throws.
    void doStep(double currentTime, double stepSize,
                bool noSetFMUStatePriorToCurrentPoint = false);

    // What a step that the FMU may refuse came to (FMI 2.0, 4.2.3):
    // completed; discarded, the FMU computed only part of the step
    // (lastSuccessfulTime() says how far); or terminated, the FMU asks to
    // end the simulation (fmi2Discard with fmi2Terminated true: its outputs
    // are those of lastSuccessfulTime()).
    enum class StepResult { completed, discarded, terminated };

    // doStep that returns fmi2Discard as discarded or terminated instead of
    // throwing; fmi2Error, fmi2Fatal and fmi2Pending throw. time() stays at
    // currentTime after a discarded or terminated step.
    StepResult tryDoStep(double currentTime, double stepSize,
                         bool noSetFMUStatePriorToCurrentPoint = false);

    // fmi2GetRealStatus(fmi2LastSuccessfulTime): after a discarded step, the
    // time up to which the FMU computed (FMI 3.0: fmi3DoStep's
    // lastSuccessfulTime; a step whose terminateSimulation is true with
    // fmi3OK is terminated too)
    double lastSuccessfulTime();

    // The FMU's last log message at fmi2Warning or above during the latest
    // call (a discarded step's reason), empty if none
    std::string lastMessage() const;

    struct Impl;

    // A saved FMU state, freed with fmi2FreeFMUstate when destroyed; it keeps
    // its instance's fmi2Component alive.
    class State {
    public:
        State();
        ~State();
        State(State&&) noexcept;
        State& operator=(State&&) noexcept;
        State(const State&) = delete;
        State& operator=(const State&) = delete;
        bool valid() const;

    private:
        friend class Instance;
        std::shared_ptr<Impl> owner_;
        void* state_;
        double
            time_; // communication point when saved; NaN after deserializeState
    };

    State getState();
    // The same into state: a state of this instance is overwritten where it
    // is (fmi2GetFMUstate given it: FMI 2.0 and 3.0 let the FMU reuse a
    // state it returned, which spares a new one and the fmi2FreeFMUstate
    // of the one it replaces), any other is replaced by a new one.
    void getState(State& state);
    void setState(
        const State& state); // restores time() too, when the state carries it
    std::vector<char> serializeState(const State& state);
    State deserializeState(const std::vector<char>& bytes);

    // Current communication point: the start time, then currentTime +
    // stepSize of the last successful doStep.
    double time() const;

private:
    std::shared_ptr<Impl> impl_;
};

} // namespace fmuImport

#endif

// The state behind an Instance: an fmi2Component in this process
// (LocalInstance) or in a child process (ChildInstance), behind one
// interface. Instance checks its arguments and keeps the communication
// point; an Impl makes the calls and checks their status.
#ifndef FMUIMPORT_INSTANCEIMPL_HPP
#define FMUIMPORT_INSTANCEIMPL_HPP

#include "FmuImpl.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fmuImport {

struct Instance::Impl {
    std::shared_ptr<Fmu::Impl> fmu;
    std::string fmuPath; // as the Fmu it was made from names it
    std::string name;
    double time = 0; // the communication point, kept by Instance

    Impl(std::shared_ptr<Fmu::Impl> fmuImpl, const std::string& path,
         const std::string& instanceName)
        : fmu(std::move(fmuImpl)), fmuPath(path), name(instanceName)
    {
    }
    virtual ~Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;

    virtual void setupExperiment(double startTime, bool stopTimeDefined,
                                 double stopTime)
        = 0;
    virtual void enterInitializationMode() = 0;
    virtual void exitInitializationMode() = 0;
    virtual void terminate() = 0;
    virtual void reset() = 0;

    virtual void setReal(const std::vector<unsigned int>& vrs,
                         const std::vector<double>& values)
        = 0;
    // The values of vrs into values, which has room for them
    virtual void getReal(const std::vector<unsigned int>& vrs, double* values)
        = 0;
    virtual void setInteger(const std::vector<unsigned int>& vrs,
                            const std::vector<int>& values)
        = 0;
    virtual std::vector<int> getInteger(const std::vector<unsigned int>& vrs)
        = 0;
    virtual void setBoolean(const std::vector<unsigned int>& vrs,
                            const std::vector<bool>& values)
        = 0;
    virtual std::vector<bool> getBoolean(const std::vector<unsigned int>& vrs)
        = 0;
    virtual void setString(const std::vector<unsigned int>& vrs,
                           const std::vector<std::string>& values)
        = 0;
    virtual std::vector<std::string>
    getString(const std::vector<unsigned int>& vrs) = 0;

    // fmi2DoStep; with mayDiscard, fmi2Discard is a result (discarded, or
    // terminated when fmi2GetBooleanStatus(fmi2Terminated) says so), else
    // it throws.
    virtual Instance::StepResult doStep(double currentTime, double stepSize,
                                        bool noSetFMUStatePriorToCurrentPoint,
                                        bool mayDiscard)
        = 0;
    virtual double lastSuccessfulTime() = 0;
    virtual std::string lastMessage() const = 0;

    // FMU states: handles that only the Impl that made them understands;
    // getState overwrites reuse, a handle it made, or makes a new one
    // (nullptr)
    virtual void* getState(void* reuse) = 0;
    virtual void setState(void* state) = 0;
    virtual void freeState(void* state) noexcept = 0;
    virtual std::vector<char> serializeState(void* state) = 0;
    virtual void* deserializeState(const std::vector<char>& bytes) = 0;
};

} // namespace fmuImport

#endif

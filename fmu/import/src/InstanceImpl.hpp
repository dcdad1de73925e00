// The state behind an Instance: the fmi2Component, its callbacks and the
// checking of every fmi2 call.
#ifndef FMUIMPORT_INSTANCEIMPL_HPP
#define FMUIMPORT_INSTANCEIMPL_HPP

#include "FmuImpl.hpp"
#include "FpTraps.hpp"

#include <memory>
#include <limits>
#include <string>

namespace fmuImport {

struct Instance::Impl {
    std::shared_ptr<Fmu::Impl> fmu;
    std::string fmuPath; // as the Fmu it was made from names it
    std::string name;
    Logger logger;
    fmi2CallbackFunctions callbacks; // the FMU may keep a pointer to it
    fmi2Component component = nullptr;
    double time = 0;
    std::string lastError; // last error the FMU logged during the current call
    std::string lastNotice; // last message at fmi2Warning or above, the same
    bool admitted = false; // counted in fmu->liveInstances

    Impl(std::shared_ptr<Fmu::Impl> fmu, const std::string& fmuPath,
         const std::string& name, Logger logger);
    ~Impl();
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;

    const Fmi2Api& api() const { return fmu->library->api(); }

    // Counts this instance among the live instances of its binary; throws
    // Error if the FMU declares canBeInstantiatedOnlyOncePerProcess and
    // another one is alive. Call before fmi2Instantiate.
    void admit();

    // Call before each fmi2 call: forgets the error text of earlier calls.
    void beginCall()
    {
        lastError.clear();
        lastNotice.clear();
    }

    // Throws Error for fmi2Error, fmi2Fatal, fmi2Discard and fmi2Pending,
    // naming function, the detail (" at t = ..."), the FMU and the
    // instance; reports fmi2Warning to the logger.
    // Throws Error for a failed call; the message gives the time when it is
    // not NaN. Formatting happens only on failure: calls are on hot paths.
    void check(fmi2Status status, const char* function,
               double time = std::numeric_limits<double>::quiet_NaN());

    // Receives a formatted message from the FMU (or from check).
    void receive(const std::string& instanceName, int status,
                 const std::string& category, const std::string& message);
};

} // namespace fmuImport

#endif

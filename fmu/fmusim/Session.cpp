#include "Session.hpp"

#include "Errors.hpp"
#include "io/Csv.hpp"

#include <iostream>

namespace fmusim {

fmuImport::Fmu loadFmu(const std::string& path,
                       const fmuImport::FmuOptions& options)
{
    try {
        return fmuImport::Fmu(path, options);
    } catch (const fmuImport::Error& e) {
        throw LoadError(e.what());
    }
}

fmuImport::Logger stderrLogger(bool verbose)
{
    return [verbose](const std::string& instance, int status,
                     const std::string& category, const std::string& message) {
        static const char* const names[]
            = {"ok", "warning", "discard", "error", "fatal", "pending"};
        if (status == 0 && !verbose)
            return;
        std::cerr << "fmusim: [" << instance << "] "
                  << (status >= 0 && status <= 5 ? names[status] : "?") << " "
                  << category << ": " << message << '\n';
    };
}

fmuImport::Logger verboseLogger(bool verbose)
{
    if (!verbose)
        return [](const std::string&, int, const std::string&,
                  const std::string&) {};
    return stderrLogger(true);
}

fmuImport::Instance instantiate(const fmuImport::Fmu& fmu,
                                const std::string& name,
                                const fmuImport::Logger& logger, bool loggingOn)
{
    try {
        return fmuImport::Instance(fmu, name, logger, loggingOn);
    } catch (const fmuImport::LostCall&) {
        throw;
    } catch (const fmuImport::Error& e) {
        throw LoadError(e.what());
    }
}

std::string instanceName(const fmuImport::Instance& instance)
{
    return "FMU '" + instance.fmuPath() + "', instance '" + instance.name()
        + "'";
}

bool stepOrEnd(fmuImport::Instance& instance, double t, double h)
{
    using Result = fmuImport::Instance::StepResult;
    const Result result = instance.tryDoStep(t, h);
    if (result == Result::completed)
        return true;
    const std::string reason = instance.lastMessage();
    if (result == Result::terminated) {
        std::cerr << "fmusim: " << instanceName(instance)
                  << " ended the simulation at t = " << formatNumber(t)
                  << (reason.empty() ? "" : ": " + reason) << '\n';
        return false;
    }
    throw fmuImport::Error(
        instanceName(instance)
        + " discarded the step from t = " + formatNumber(t) + " to "
        + formatNumber(t + h) + " (last successful time "
        + formatNumber(instance.lastSuccessfulTime())
        + ") without asking to end the simulation"
        + (reason.empty() ? "" : ": " + reason)
        + "; fmusim takes the steps it is given and cannot retry a shorter one");
}

} // namespace fmusim

#include "Session.hpp"

#include "Errors.hpp"

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

fmuImport::Instance instantiate(const fmuImport::Fmu& fmu,
                                const std::string& name, bool loggingOn)
{
    try {
        return fmuImport::Instance(fmu, name, stderrLogger(loggingOn),
                                   loggingOn);
    } catch (const fmuImport::LostCall&) {
        throw;
    } catch (const fmuImport::Error& e) {
        throw LoadError(e.what());
    }
}

} // namespace fmusim

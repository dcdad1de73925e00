// Loading an FMU and instantiating it, with failures turned into LoadError
// (exit code 3).
#ifndef FMUSIM_SESSION_HPP
#define FMUSIM_SESSION_HPP

#include "WatchedInstance.hpp"

#include "fmuImport/fmuImport.hpp"

#include <string>

namespace fmusim {

fmuImport::Fmu loadFmu(const std::string& path);

// An instance whose log messages go to standard error, prefixed by the
// status; loggingOn switches on the FMU's debug logging.
WatchedInstance instantiate(const fmuImport::Fmu& fmu, const std::string& name,
                            bool loggingOn);

// Logs to standard error everything but fmi2OK messages, unless verbose.
fmuImport::Logger stderrLogger(bool verbose);

} // namespace fmusim

#endif

// Loading an FMU and instantiating it, with failures turned into LoadError
// (exit code 3); a call that does not come back (fmuImport::LostCall) stays
// what it is (exit code 6 or 7, main.cpp).
#ifndef FMUSIM_SESSION_HPP
#define FMUSIM_SESSION_HPP

#include "fmuImport/fmuImport.hpp"

#include <string>

namespace fmusim {

// The FMU with its instances' isolation and time limit (--isolation,
// --timeout).
fmuImport::Fmu loadFmu(const std::string& path,
                       const fmuImport::FmuOptions& options);

// An instance whose log messages go to standard error, prefixed by the
// status; loggingOn switches on the FMU's debug logging.
fmuImport::Instance instantiate(const fmuImport::Fmu& fmu,
                                const std::string& name, bool loggingOn);

// Logs to standard error everything but fmi2OK messages, unless verbose.
fmuImport::Logger stderrLogger(bool verbose);

} // namespace fmusim

#endif

// The FMU as every subcommand drives it: loaded and instantiated with
// failures turned into LoadError (exit code 3), a call that does not come
// back (fmuImport::LostCall) left what it is (exit code 6 or 7, main.cpp),
// its log on standard error, and its steps taken as given.
#ifndef FMUSIM_SESSION_HPP
#define FMUSIM_SESSION_HPP

#include "fmuImport/fmuImport.hpp"

#include <string>

namespace fmusim {

// The FMU with its instances' isolation and time limit (--isolation,
// --timeout).
fmuImport::Fmu loadFmu(const std::string& path,
                       const fmuImport::FmuOptions& options);

// An instance whose log messages go to logger; loggingOn switches on the
// FMU's debug logging.
fmuImport::Instance instantiate(const fmuImport::Fmu& fmu,
                                const std::string& name,
                                const fmuImport::Logger& logger,
                                bool loggingOn);

// Logs to standard error, prefixed by the status, everything but fmi2OK
// messages, unless verbose.
fmuImport::Logger stderrLogger(bool verbose);

// Logs everything to standard error as stderrLogger does when verbose,
// nothing otherwise.
fmuImport::Logger verboseLogger(bool verbose);

// "FMU 'x.fmu', instance 'x'", as fmusim's messages name an instance.
std::string instanceName(const fmuImport::Instance& instance);

// One fmi2DoStep from t by h. Returns true when the step was taken, false
// when the FMU asks to end the simulation (fmi2Discard with fmi2Terminated,
// reported on stderr with the FMU's reason); a step the FMU discards without
// asking to end throws fmuImport::Error: fmusim takes the steps it was given
// and cannot retry a shorter one.
bool stepOrEnd(fmuImport::Instance& instance, double t, double h);

} // namespace fmusim

#endif

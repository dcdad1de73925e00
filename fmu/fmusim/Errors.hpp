// Exit codes of fmusim and the exception class behind each: a failed FMU
// call or a simulation that could not go on is the importer's
// fmuImport::Error, a call that did not come back its fmuImport::LostCall.
#ifndef FMUSIM_ERRORS_HPP
#define FMUSIM_ERRORS_HPP

#include <stdexcept>

namespace fmusim {

enum ExitCode {
    exitOk = 0,
    exitCheckFailed = 1, // `check` found at least one FAIL
    exitUsage = 2, // bad command line
    exitLoad = 3, // the FMU could not be loaded or instantiated
    exitFile
    = 4, // an input file is unreadable or malformed, or an output file cannot be written
    exitSimulation = 5, // an FMU call failed or the simulation broke down
    exitTimeout = 6, // an FMU call did not return within --timeout
    exitFmuEnded = 7 // the FMU crashed or exited in a call (--isolation
    // process; in fmusim's process a crash ends fmusim by its signal, an
    // exit(0) with this code)
};

// The command line is wrong.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A file is unreadable or malformed (message: file:line: problem).
class FileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The FMU could not be loaded or instantiated.
class LoadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace fmusim

#endif

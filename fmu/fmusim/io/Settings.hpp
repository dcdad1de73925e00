// `name = value` settings from files (parameter files, twobody
// configurations) and --set options, and applying them to FMU variables.
#ifndef FMUSIM_IO_SETTINGS_HPP
#define FMUSIM_IO_SETTINGS_HPP

#include "fmuImport/fmuImport.hpp"

#include <string>
#include <vector>

namespace fmusim {

struct Setting {
    std::string name;
    std::string value;
    std::string origin; // "file:line", or "--set" for the command line
    bool fromFile = false;
};

// One `name = value` per line; '#' starts a comment; blank lines are
// skipped. FileError "file:line: problem" for a line without '=' or name.
std::vector<Setting> readSettingsFile(const std::string& path);

// Parses --set options "name=value"; UsageError otherwise.
std::vector<Setting> parseSetOptions(const std::vector<std::string>& options);

struct Args;

// The FMU settings of a command line: those of the --parameters file (the
// last one given), then the --set options in order.
std::vector<Setting> fmuSettings(const Args& args);

// The variable may be given a value before initialization (FMI 2.0, 3.2.3
// and 4.2.4): a parameter or an input, any tunable variable, and any
// variable that is not constant and has a start value, as an output or
// local with initial="exact" or "approx" has (Reference FMUs' BouncingBall
// h). Settings are applied in the instantiated state, before
// fmi2EnterInitializationMode, where all of these may be set.
bool isSettable(const fmuImport::Variable& v);

// Sets each setting on the instance, converted to the variable's type.
// Unknown or unsettable variables and values of the wrong type throw
// FileError (settings from a file) or UsageError (from --set), naming the
// origin.
void applySettings(const fmuImport::Fmu& fmu, fmuImport::Instance& instance,
                   const std::vector<Setting>& settings);

} // namespace fmusim

#endif

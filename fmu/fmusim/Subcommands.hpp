// The subcommands of fmusim, each its help text and its entry point. An
// entry point takes everything after the subcommand's name, returns the exit
// code and throws the classes of Errors.hpp.
//   run      simulate any FMI 2.0 co-simulation FMU with inputs from a CSV
//            table and outputs to CSV
//   check    validate a connector FMU against docs/connector-fmu-interface.md
//            and probe its behaviour; returns exitOk or exitCheckFailed
//   twobody  two rigid bodies coupled through a connector FMU
#ifndef FMUSIM_SUBCOMMANDS_HPP
#define FMUSIM_SUBCOMMANDS_HPP

#include <string>
#include <vector>

namespace fmusim {

const char* runUsage();
int runCommand(const std::vector<std::string>& args);

const char* checkUsage();
int checkCommand(const std::vector<std::string>& args);

const char* twoBodyUsage();
int twoBodyCommand(const std::vector<std::string>& args);

} // namespace fmusim

#endif

// `fmusim run`: simulate any FMI 2.0 co-simulation FMU with inputs from a
// CSV table and outputs to CSV.
#ifndef FMUSIM_RUN_RUN_HPP
#define FMUSIM_RUN_RUN_HPP

#include <string>
#include <vector>

namespace fmusim {

// The help text of the subcommand.
const char* runUsage();

// args: everything after "run". Returns the exit code; throws the classes
// of Errors.hpp.
int runCommand(const std::vector<std::string>& args);

} // namespace fmusim

#endif

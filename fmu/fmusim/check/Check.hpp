// `fmusim check`: validate a connector FMU against
// docs/connector-fmu-interface.md and probe its behaviour.
#ifndef FMUSIM_CHECK_CHECK_HPP
#define FMUSIM_CHECK_CHECK_HPP

#include <string>
#include <vector>

namespace fmusim {

const char* checkUsage();

// args: everything after "check". Returns exitOk or exitCheckFailed.
int checkCommand(const std::vector<std::string>& args);

struct CheckResult {
    enum Outcome { pass, fail, skip };
    std::string name;
    Outcome outcome;
    std::string reason; // why it failed or was skipped
};

} // namespace fmusim

#endif

// `fmusim check` (Subcommands.hpp): the result of one of its checks.
#ifndef FMUSIM_CHECK_CHECK_HPP
#define FMUSIM_CHECK_CHECK_HPP

#include <string>
#include <vector>

namespace fmusim {

struct CheckResult {
    enum Outcome { pass, fail, skip };
    std::string name;
    Outcome outcome;
    std::string reason; // why it failed or was skipped
};

} // namespace fmusim

#endif

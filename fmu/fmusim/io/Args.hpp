// Command-line parsing shared by the subcommands: positional arguments,
// `--name value` or `--name=value` options (repeatable) and flags.
#ifndef FMUSIM_IO_ARGS_HPP
#define FMUSIM_IO_ARGS_HPP

#include "fmuImport/fmuImport.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fmusim {

struct Args {
    std::vector<std::string> positional;
    std::map<std::string, std::vector<std::string>>
        options; // name without "--" -> values in order
    std::set<std::string> flags;

    // The last value of option, if given.
    std::optional<std::string> last(const std::string& option) const;
    // The last value as a number; UsageError naming the option otherwise.
    std::optional<double> number(const std::string& option) const;
    bool flag(const std::string& name) const { return flags.count(name) != 0; }
};

// --timeout: the longest a call into the FMU may take [s], 0 (the default)
// for no limit; UsageError unless a non-negative number.
double timeoutOption(const Args& args);

// --isolation: none (the default) or process; UsageError otherwise.
fmuImport::Isolation isolationOption(const Args& args);

// Parses none or process; nullopt otherwise.
std::optional<fmuImport::Isolation> toIsolation(const std::string& text);

// Throws UsageError for an option not in valueOptions or flagOptions, or an
// option without its value.
Args parseArgs(const std::vector<std::string>& args,
               const std::set<std::string>& valueOptions,
               const std::set<std::string>& flagOptions);

// Parses a whole string as a finite double.
std::optional<double> toNumber(const std::string& text);

// Splits at commas outside square brackets ("A.R[1,1],y" -> "A.R[1,1]", "y").
std::vector<std::string> splitNames(const std::string& list);

// Removes leading and trailing blanks.
std::string trim(const std::string& s);

} // namespace fmusim

#endif

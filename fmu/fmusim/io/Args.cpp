#include "io/Args.hpp"

#include "Errors.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace fmusim {

std::optional<std::string> Args::last(const std::string& option) const
{
    const auto found = options.find(option);
    if (found == options.end() || found->second.empty())
        return std::nullopt;
    return found->second.back();
}

std::optional<double> Args::number(const std::string& option) const
{
    const std::optional<std::string> text = last(option);
    if (!text)
        return std::nullopt;
    const std::optional<double> value = toNumber(*text);
    if (!value)
        throw UsageError("--" + option + ": '" + *text
                         + "' is not a finite number");
    return value;
}

double timeoutOption(const Args& args)
{
    const std::optional<std::string> text = args.last("timeout");
    if (!text)
        return 0;
    const std::optional<double> seconds = toNumber(*text);
    if (!seconds || *seconds < 0)
        throw UsageError(
            "--timeout must be a non-negative number of seconds, found '"
            + *text + "'");
    return *seconds;
}

std::optional<fmuImport::Isolation> toIsolation(const std::string& text)
{
    if (text == "none")
        return fmuImport::Isolation::none;
    if (text == "process")
        return fmuImport::Isolation::process;
    return std::nullopt;
}

fmuImport::Isolation isolationOption(const Args& args)
{
    const std::optional<std::string> text = args.last("isolation");
    if (!text)
        return fmuImport::Isolation::none;
    const std::optional<fmuImport::Isolation> isolation = toIsolation(*text);
    if (!isolation)
        throw UsageError("--isolation must be none or process, found '" + *text
                         + "'");
    return *isolation;
}

Args parseArgs(const std::vector<std::string>& args,
               const std::set<std::string>& valueOptions,
               const std::set<std::string>& flagOptions)
{
    Args parsed;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) {
            parsed.positional.push_back(arg);
            continue;
        }
        std::string name = arg.substr(2);
        std::optional<std::string> value;
        const std::size_t equals = name.find('=');
        if (equals != std::string::npos) {
            value = name.substr(equals + 1);
            name = name.substr(0, equals);
        }
        if (flagOptions.count(name)) {
            if (value)
                throw UsageError("--" + name + " takes no value");
            parsed.flags.insert(name);
            continue;
        }
        if (!valueOptions.count(name))
            throw UsageError("unknown option --" + name);
        if (!value) {
            if (i + 1 >= args.size())
                throw UsageError("--" + name + " needs a value");
            value = args[++i];
        }
        parsed.options[name].push_back(*value);
    }
    return parsed;
}

std::optional<double> toNumber(const std::string& text)
{
    const std::string s = trim(text);
    if (s.empty())
        return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(s.c_str(), &end);
    if (*end != '\0' || errno == ERANGE || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::vector<std::string> splitNames(const std::string& list)
{
    std::vector<std::string> names;
    std::string current;
    int depth = 0;
    for (const char c : list) {
        if (c == '[')
            ++depth;
        if (c == ']')
            --depth;
        if (c == ',' && depth == 0) {
            names.push_back(trim(current));
            current.clear();
        } else {
            current += c;
        }
    }
    names.push_back(trim(current));
    return names;
}

std::string trim(const std::string& s)
{
    const std::size_t begin = s.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos)
        return std::string();
    const std::size_t end = s.find_last_not_of(" \t\r\n");
    return s.substr(begin, end - begin + 1);
}

} // namespace fmusim

#include "io/Settings.hpp"

#include "Errors.hpp"
#include "io/Args.hpp"

#include <cmath>
#include <fstream>

namespace fmusim {

namespace {

[[noreturn]] void reject(const Setting& s, const std::string& problem)
{
    const std::string message = s.origin + ": " + problem;
    if (s.fromFile)
        throw FileError(message);
    throw UsageError(message);
}

} // namespace

std::vector<Setting> readSettingsFile(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw FileError(path + ": cannot be read");
    std::vector<Setting> settings;
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        const std::string content = trim(line.substr(0, line.find('#')));
        if (content.empty())
            continue;
        const std::string origin = path + ":" + std::to_string(lineNumber);
        const std::size_t equals = content.find('=');
        if (equals == std::string::npos)
            throw FileError(origin + ": expected 'name = value', found '"
                            + content + "'");
        Setting s {trim(content.substr(0, equals)),
                   trim(content.substr(equals + 1)), origin, true};
        if (s.name.empty())
            throw FileError(origin + ": no name before '='");
        settings.push_back(s);
    }
    return settings;
}

std::vector<Setting> parseSetOptions(const std::vector<std::string>& options)
{
    std::vector<Setting> settings;
    for (const std::string& option : options) {
        const std::size_t equals = option.find('=');
        if (equals == std::string::npos
            || trim(option.substr(0, equals)).empty())
            throw UsageError("--set: expected name=value, found '" + option
                             + "'");
        settings.push_back({trim(option.substr(0, equals)),
                            trim(option.substr(equals + 1)), "--set", false});
    }
    return settings;
}

std::vector<Setting> fmuSettings(const Args& args)
{
    std::vector<Setting> settings;
    if (const auto file = args.last("parameters"))
        settings = readSettingsFile(*file);
    if (args.options.count("set")) {
        const std::vector<Setting> set
            = parseSetOptions(args.options.at("set"));
        settings.insert(settings.end(), set.begin(), set.end());
    }
    return settings;
}

bool isSettable(const fmuImport::Variable& v)
{
    using fmuImport::Causality;
    const bool initialExactOrApprox = v.hasStart
        && v.variability != fmuImport::Variability::constant
        && (v.causality == Causality::output
            || v.causality == Causality::local);
    return v.causality == Causality::parameter
        || v.causality == Causality::input
        || v.variability == fmuImport::Variability::tunable
        || initialExactOrApprox;
}

void applySettings(const fmuImport::Fmu& fmu, fmuImport::Instance& instance,
                   const std::vector<Setting>& settings)
{
    using fmuImport::Type;
    for (const Setting& s : settings) {
        if (!fmu.hasVariable(s.name))
            reject(s,
                   "FMU '" + fmu.path() + "' has no variable '" + s.name + "'");
        const fmuImport::Variable& v = fmu.variable(s.name);
        if (!isSettable(v))
            reject(
                s,
                "variable '" + s.name
                    + "' cannot be set before initialization: it is neither a parameter nor an input and has no start value");
        const std::vector<unsigned int> vr {v.valueReference};
        if (v.type == Type::String) {
            instance.setString(vr, {s.value});
            continue;
        }
        if (v.type == Type::Boolean) {
            if (s.value != "true" && s.value != "false" && s.value != "1"
                && s.value != "0")
                reject(s,
                       "'" + s.value + "' for Boolean '" + s.name
                           + "' is not true, false, 1 or 0");
            instance.setBoolean(vr, {s.value == "true" || s.value == "1"});
            continue;
        }
        const std::optional<double> number = toNumber(s.value);
        if (!number)
            reject(s,
                   "'" + s.value + "' for '" + s.name
                       + "' is not a finite number");
        if (v.type == Type::Real) {
            instance.setReal(vr, {*number});
            continue;
        }
        if (*number != std::floor(*number) || std::fabs(*number) > 2147483647.0)
            reject(s,
                   "'" + s.value + "' for '" + s.name + "' is not an integer");
        instance.setInteger(vr, {static_cast<int>(*number)});
    }
}

} // namespace fmusim

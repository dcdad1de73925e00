#include "io/Settings.hpp"

#include <iostream>

#include "io/Args.hpp"
#include "io/Csv.hpp"
#include "Errors.hpp"

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

bool stepOrEnd(fmuImport::Instance& instance, double t, double h)
{
    using Result = fmuImport::Instance::StepResult;
    const Result result = instance.tryDoStep(t, h);
    if (result == Result::completed)
        return true;
    const std::string reason = instance.lastMessage();
    const std::string who = "FMU '" + instance.fmuPath() + "', instance '"
        + instance.name() + "'";
    if (result == Result::terminated) {
        std::cerr << "fmusim: " << who
                  << " ended the simulation at t = " << formatNumber(t)
                  << (reason.empty() ? "" : ": " + reason) << '\n';
        return false;
    }
    throw SimulationError(
        who + " discarded the step from t = " + formatNumber(t) + " to "
        + formatNumber(t + h) + " (last successful time "
        + formatNumber(instance.lastSuccessfulTime())
        + ") without asking to end the simulation"
        + (reason.empty() ? "" : ": " + reason)
        + "; fmusim takes the steps it is given and cannot retry a shorter one");
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

std::vector<std::string>
readValues(fmuImport::Instance& instance,
           const std::vector<const fmuImport::Variable*>& variables)
{
    using fmuImport::Type;
    // One fmi2Get call per type: gather the value references, then scatter.
    std::vector<unsigned int> vrs[4];
    std::vector<std::size_t> where[4];
    auto group = [](Type t) {
        return t == Type::Real   ? 0
            : t == Type::Boolean ? 2
            : t == Type::String  ? 3
                                 : 1;
    };
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const int g = group(variables[i]->type);
        vrs[g].push_back(variables[i]->valueReference);
        where[g].push_back(i);
    }
    std::vector<std::string> text(variables.size());
    if (!vrs[0].empty()) {
        const std::vector<double> values = instance.getReal(vrs[0]);
        for (std::size_t k = 0; k < values.size(); ++k) {
            const fmuImport::Variable& v = *variables[where[0][k]];
            if (!std::isfinite(values[k]))
                throw SimulationError(nonFiniteMessage(
                    instance,
                    (v.causality == fmuImport::Causality::output ? "output '"
                                                                 : "variable '")
                        + v.name + "'",
                    values[k], instance.time()));
            text[where[0][k]] = formatNumber(values[k]);
        }
    }
    if (!vrs[1].empty()) {
        const std::vector<int> values = instance.getInteger(vrs[1]);
        for (std::size_t k = 0; k < values.size(); ++k)
            text[where[1][k]] = std::to_string(values[k]);
    }
    if (!vrs[2].empty()) {
        const std::vector<bool> values = instance.getBoolean(vrs[2]);
        for (std::size_t k = 0; k < values.size(); ++k)
            text[where[2][k]] = values[k] ? "1" : "0";
    }
    if (!vrs[3].empty()) {
        const std::vector<std::string> values = instance.getString(vrs[3]);
        for (std::size_t k = 0; k < values.size(); ++k)
            text[where[3][k]] = csvField(values[k]);
    }
    return text;
}

std::string nonFiniteMessage(const fmuImport::Instance& instance,
                             const std::string& what, double value, double time)
{
    return "FMU '" + instance.fmuPath() + "', instance '" + instance.name()
        + "': " + what + " is " + formatNumber(value)
        + " at t = " + formatNumber(time) + ", expected a finite number";
}

} // namespace fmusim

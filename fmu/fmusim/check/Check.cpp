#include "check/Check.hpp"

#include "Subcommands.hpp"

#include "io/Args.hpp"
#include "check/CheckProbes.hpp"
#include "Errors.hpp"
#include "Session.hpp"

#include <algorithm>
#include <iostream>

namespace fmusim {

const char* checkUsage()
{
    return "fmusim check connector.fmu [--seed N] [--samples N] [--verbose] [--timeout SECONDS]\n"
           "                           [--isolation none|process]\n"
           "  Validates a connector FMU against docs/connector-fmu-interface.md: required\n"
           "  and optional variables (causality, variability, units), capabilities and\n"
           "  parameter start values; then probes it: equal and opposite forces and zero\n"
           "  total moment for random kinematics (--samples configurations drawn with\n"
           "  --seed, default 20 and 1), zero load at a declared rest configuration, FMU\n"
           "  state get/set and serialization, a repeated step after restoring the state,\n"
           "  variable step sizes, and fmi2Error (never a non-finite output) for\n"
           "  non-finite inputs. Prints 'PASS name', 'FAIL name: reason' or\n"
           "  'SKIP name: reason' per check and 'N passed, M failed' at the end.\n"
           "  --verbose prints the FMU's log messages. --timeout ends the check (exit code\n"
           "  6) when one call into the FMU takes longer; default 0: no limit. With\n"
           "  --isolation process each probe's instance runs in a process of its own: a\n"
           "  crash, exit or time-out of the FMU fails that check and the next goes on.\n";
}

namespace {

using fmuImport::Causality;
using fmuImport::connector::Problem;

std::string joined(const std::vector<std::string>& problems)
{
    std::string text;
    const std::size_t shown = std::min<std::size_t>(problems.size(), 6);
    for (std::size_t i = 0; i < shown; ++i)
        text += (i ? "; " : "") + problems[i];
    if (problems.size() > shown)
        text += "; and " + std::to_string(problems.size() - shown) + " more";
    return text;
}

CheckResult verdict(const std::string& name,
                    const std::vector<std::string>& problems)
{
    return problems.empty()
        ? CheckResult {name, CheckResult::pass, ""}
        : CheckResult {name, CheckResult::fail, joined(problems)};
}

std::vector<CheckResult> interfaceChecks(const fmuImport::Fmu& fmu,
                                         const ConnectorIo& connector)
{
    std::vector<std::string> missing, optional, units;
    for (const Problem& p : connector.variables().problems())
        (p.kind == Problem::Kind::unit ? units
             : p.required              ? missing
                                       : optional)
            .push_back(p.text);

    std::vector<std::string> capabilities;
    if (!fmu.modelDescription().canHandleVariableCommunicationStepSize)
        capabilities.push_back(
            "canHandleVariableCommunicationStepSize is not true");

    std::vector<std::string> parameters;
    for (const fmuImport::Variable& v : fmu.modelDescription().variables) {
        if (v.causality != Causality::parameter)
            continue;
        if (!v.hasStart)
            parameters.push_back(v.name + " has no start value");
        if (v.description.empty())
            parameters.push_back(v.name + " has no description");
    }

    return {verdict("required-variables", missing),
            verdict("optional-variables", optional), verdict("units", units),
            verdict("capabilities", capabilities),
            verdict("parameters", parameters)};
}

} // namespace

int checkCommand(const std::vector<std::string>& arguments)
{
    const Args args = parseArgs(
        arguments, {"seed", "samples", "timeout", "isolation"}, {"verbose"});
    if (args.positional.size() != 1)
        throw UsageError("check needs exactly one FMU file");
    ProbeOptions options;
    if (const auto seed = args.number("seed")) {
        if (*seed < 0 || *seed != static_cast<unsigned int>(*seed))
            throw UsageError("--seed must be a non-negative integer");
        options.seed = static_cast<unsigned int>(*seed);
    }
    if (const auto samples = args.number("samples")) {
        if (*samples < 1 || *samples > 1e6
            || *samples != static_cast<int>(*samples))
            throw UsageError("--samples must be an integer from 1 to 1000000");
        options.samples = static_cast<int>(*samples);
    }
    options.verbose = args.flag("verbose");
    const fmuImport::Fmu fmu
        = loadFmu(args.positional[0],
                  {isolationOption(args), timeoutOption(args), std::string()});
    const ConnectorIo connector(fmu);

    int passed = 0, failed = 0;
    auto report = [&](const CheckResult& r) {
        if (r.outcome == CheckResult::pass) {
            ++passed;
            std::cout << "PASS " << r.name << '\n';
        } else {
            failed += r.outcome == CheckResult::fail;
            std::cout << (r.outcome == CheckResult::fail ? "FAIL " : "SKIP ")
                      << r.name << ": " << r.reason << '\n';
        }
        std::cout.flush();
    };
    for (const CheckResult& r : interfaceChecks(fmu, connector))
        report(r);
    // An FMU that cannot be instantiated (a GUID mismatch, a failing
    // fmi2Instantiate) is a load error, exit code 3 as for run and twobody,
    // not merely a failed check: nothing else can be checked. The report
    // still ends with its reason and the count.
    // fmi2Instantiate and fmi2FreeInstance, the FMU's messages shown only
    // when verbose (as in the probes).
    try {
        instantiate(fmu, "check", verboseLogger(options.verbose), false);
    } catch (const LoadError& e) {
        report({"initialization", CheckResult::fail, e.what()});
        std::cout << passed << " passed, " << failed << " failed\n";
        throw;
    }
    if (connector.variables().missingRequired().empty())
        runProbes(fmu, connector, options, report);
    else
        report({"probes", CheckResult::skip,
                "the required variables are not all declared"});
    std::cout << passed << " passed, " << failed << " failed\n";
    return failed ? exitCheckFailed : exitOk;
}

} // namespace fmusim

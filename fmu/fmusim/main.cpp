// fmusim: run, check and couple FMI 2.0 co-simulation FMUs without CFD.
#include "Errors.hpp"
#include "Subcommands.hpp"

#include "fmuImport/fmuImport.hpp"

#include <signal.h>

#include <algorithm>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace {

const char* const exitCodes
    = "Exit codes:\n"
      "  0  success\n"
      "  1  check: at least one check failed\n"
      "  2  usage error: unknown subcommand or option, missing or malformed value\n"
      "  3  the FMU could not be loaded or instantiated\n"
      "  4  bad file: input table, parameter or configuration file unreadable or\n"
      "     malformed, or naming an unknown variable; output file not writable\n"
      "  5  simulation error: an FMU call failed, an output became NaN or infinite,\n"
      "     the coupling did not converge or a body state became non-finite\n"
      "  6  time-out: a call into the FMU did not return within --timeout seconds\n"
      "  7  the FMU crashed or exited in a call (--isolation process; without it a\n"
      "     crash ends fmusim by the FMU's signal, and an exit(0) ends it with 7)\n";

void printHelp(std::ostream& out)
{
    out << "Usage: fmusim <subcommand> ... (fmusim <subcommand> --help for its options)\n\n"
        << fmusim::runUsage() << '\n'
        << fmusim::checkUsage() << '\n'
        << fmusim::twoBodyUsage() << '\n'
        << exitCodes;
}

bool wantsHelp(const std::vector<std::string>& args)
{
    for (const std::string& a : args)
        if (a == "--help" || a == "-h")
            return true;
    return false;
}

int dispatch(const std::string& command, const std::vector<std::string>& args)
{
    struct Subcommand {
        const char* name;
        const char* (*usage)();
        int (*run)(const std::vector<std::string>&);
    };
    static const Subcommand subcommands[] = {
        {"run", fmusim::runUsage, fmusim::runCommand},
        {"check", fmusim::checkUsage, fmusim::checkCommand},
        {"twobody", fmusim::twoBodyUsage, fmusim::twoBodyCommand},
    };
    for (const Subcommand& s : subcommands) {
        if (command != s.name)
            continue;
        if (wantsHelp(args))
            return std::cout << s.usage() << '\n' << exitCodes, fmusim::exitOk;
        return s.run(args);
    }
    throw fmusim::UsageError("unknown subcommand '" + command
                             + "' (run, check or twobody)");
}

// How the importer reports an FMU that crashes, hangs or exits in a call in
// fmusim's process (the default, --isolation none): a line on standard
// error naming the call, then the FMU's signal ends fmusim, or the exit
// codes 6 and 7. Rows are written through (CsvWriter): the output holds
// every row before the call. The handlers run on an alternate stack, so
// that an FMU that overflows the stack is reported too.
void setUpReports()
{
    static char alternateStack[64 * 1024];
    stack_t stack {};
    stack.ss_sp = alternateStack;
    stack.ss_size = sizeof alternateStack;
    sigaltstack(&stack, nullptr);
    fmuImport::setReports({"fmusim: ", " (--timeout)", fmusim::exitTimeout,
                           fmusim::exitFmuEnded});
}

} // namespace

int main(int argc, char** argv)
{
    setUpReports();
    const std::vector<std::string> args(argv + std::min(argc, 2), argv + argc);
    if (argc < 2 || !std::strcmp(argv[1], "--help")
        || !std::strcmp(argv[1], "-h")) {
        printHelp(argc < 2 ? std::cerr : std::cout);
        return argc < 2 ? fmusim::exitUsage : fmusim::exitOk;
    }
    try {
        return dispatch(argv[1], args);
    } catch (const fmusim::UsageError& e) {
        std::cerr << "fmusim: usage error: " << e.what()
                  << "\n(fmusim --help lists the options)\n";
        return fmusim::exitUsage;
    } catch (const fmusim::LoadError& e) {
        std::cerr << "fmusim: cannot load the FMU: " << e.what() << '\n';
        return fmusim::exitLoad;
    } catch (const fmusim::FileError& e) {
        std::cerr << "fmusim: bad file: " << e.what() << '\n';
        return fmusim::exitFile;
    } catch (const fmuImport::LostCall& e) {
        std::cerr << "fmusim: " << e.what() << '\n';
        return e.reason() == fmuImport::LostCall::Reason::timedOut
            ? fmusim::exitTimeout
            : fmusim::exitFmuEnded;
    } catch (const std::exception& e) {
        // fmuImport::Error after loading: an FMU call failed, or fmusim
        // found the simulation broken (a non-finite output or body state, a
        // coupling that did not converge, a discarded step).
        std::cerr << "fmusim: simulation error: " << e.what() << '\n';
        return fmusim::exitSimulation;
    }
}

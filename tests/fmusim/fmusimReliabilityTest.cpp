// fmusim against misbehaving FMUs (faultySpring: NaN outputs, a crash or an
// endless loop from a given time on; hangingSpring: every step hangs;
// faultyBungee-<fault>: the example's bungee that crashes, aborts, exits or
// hangs), in its own process and in one of the FMU's own (--isolation
// process): a clear message, a documented exit code, and every row before
// the fault on disk.
#include "fmusimTest.hpp"

#include <cmath>
#include <csignal>
#include <ostream>
#include <utility>
#include <vector>

namespace {

using namespace harness;

// The rows of a CSV with communication points k h, k = 0..last.
void expectRowsUpTo(const std::string& csv, double h, int last)
{
    const harness::Table t = harness::readTable(csv);
    ASSERT_EQ(t.rows.size(), static_cast<std::size_t>(last + 1)) << csv;
    for (int k = 0; k <= last; ++k) {
        EXPECT_EQ(t.rows[k][0], k * h) << csv << " row " << k;
        for (const double value : t.rows[k])
            EXPECT_TRUE(std::isfinite(value)) << csv << " row " << k;
    }
}

// fmusim run, check and twobody of testSpring with `option`: each command
// and its result
std::vector<std::pair<std::string, Result>>
eachCommand(const std::string& option)
{
    std::vector<std::pair<std::string, Result>> results;
    for (const std::string command : {"run", "check", "twobody"})
        results.emplace_back(
            command,
            fmusim(command + " " + fixture("testSpring") + " " + option));
    return results;
}

// A run of a faulty FMU that ends at the fault, with every row before it
// on disk: options, then how it ends (exit code, or the signal that
// killed fmusim), the message on standard error (around the FMU's path),
// and the rows: communication points k h, k = 0..lastRow.
struct FaultRun {
    const char* name;
    const char* command; // run or twobody
    const char* fmu; // a fixture
    const char* options; // before --output-file
    int exitCode; // for the runs fmusim ends itself
    int signal; // for the runs the fault kills fmusim in; else 0
    const char* messageBefore; // the message: before the FMU's path...
    const char* messageAfter; // ... and after it ("": no message checked)
    bool timesOut; // --timeout ends it within seconds
    double h;
    int lastRow;
};

const FaultRun faultRuns[] = {
    // Steps of 1/4 s, exact in binary: A.F[1] is NaN from the step at 0.5
    // on, so from the row for 0.75.
    {"RunStopsAtANonFiniteOutput", "run", "faultySpring",
     "--set nanTime=0.3 --step-size 0.25 --stop-time 2", 5, 0, "FMU '",
     "', instance 'faultySpring': output 'A.F[1]' is nan at t = 0.75, "
     "expected a finite number",
     false, 0.25, 2},
    // Both bodies fixed: the NaN load moves nothing, only the check stops it.
    {"TwoBodyStopsAtANonFiniteOutput", "twobody", "faultySpring",
     "--set nanTime=0.3 --step-size 0.25 --stop-time 2 --B.position 1,0,0 "
     "--A.motion fixed --B.motion fixed",
     5, 0, "FMU '",
     "', instance 'twobody': output 'A.F[1]' is nan at t = 0.75, expected a "
     "finite number",
     false, 0.25, 2},
    // A segmentation fault in fmi2DoStep at t = 0.75 with steps of 1/1024 s:
    // fmusim dies of it, says where, and the 769 rows before are on disk (30
    // kB, more than an output buffer holds, and not a multiple of it).
    {"RowsSurviveACrashInTheFmu", "run", "faultySpring",
     "--set crashTime=0.75 --step-size 0.0009765625", 0, SIGSEGV,
     "fmusim: the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep at "
     "t = 0.75 in FMU '",
     "', instance 'faultySpring'", false, 0.0009765625, 768},
    // Two bodies joined by the spring, B released 0.1 m from its rest
    // position: rows of moving bodies, longer ones.
    {"RowsSurviveACrashInTwoBody", "twobody", "faultySpring",
     "--set crashTime=0.75 --B.position 1.1,0,0 --step-size 0.00390625 "
     "--stop-time 1",
     0, SIGSEGV, "", "", false, 0.00390625, 192},
    // fmi2DoStep at t = 0.75 never returns: --timeout 1 ends the run within
    // a few seconds, with exit code 6, a message naming the call, and the
    // rows before it on disk.
    {"RunTimesOutInAnEndlessStep", "run", "faultySpring",
     "--set hangTime=0.75 --step-size 0.00390625 --timeout 1", 6, 0,
     "fmusim: time-out: fmi2DoStep at t = 0.75 in FMU '",
     "', instance 'faultySpring' did not return within 1 s (--timeout)", true,
     0.00390625, 192},
    {"TwoBodyTimesOutInAnEndlessStep", "twobody", "faultySpring",
     "--set hangTime=0.3 --B.position 1,0,0 --step-size 0.25 --stop-time 2 "
     "--timeout 0.5",
     6, 0, "fmi2DoStep at t = 0.5 in FMU '",
     "', instance 'twobody' did not return within 0.5 s", true, 0.25, 2},
    // In fmusim's own process an FMU's exit(0) would end fmusim with status
    // 0, a success: the importer's exit hook names the call and makes it 7.
    {"ExitInTheFmuIsNamedAndNotASuccess", "run", "faultyBungee-exit",
     "--step-size 0.0625", 7, 0,
     "fmusim: the FMU exited (status 0) in fmi2DoStep at t = 0.25 in FMU '",
     "', instance 'bungee'\n", false, 0.0625, 4},
};

// A case by its name in GoogleTest's messages
void PrintTo(const FaultRun& c, std::ostream* os)
{
    *os << c.name;
}

class FmusimFault : public ::testing::TestWithParam<FaultRun> { };

TEST_P(FmusimFault, EndsAtTheFaultWithTheRowsBefore)
{
    const FaultRun& c = GetParam();
    const CsvRun run
        = fmusimCsv(c.command, c.fmu, c.options, c.timesOut ? 60 : 600);
    const harness::Result& r = run.result;
    const std::string message = *c.messageAfter == '\0'
        ? ""
        : c.messageBefore + fixture(c.fmu) + c.messageAfter;
    if (c.signal != 0) {
        EXPECT_EQ(r.signal, c.signal) << "exit code " << r.exitCode << "\n"
                                      << r.err;
        if (!message.empty()) {
            EXPECT_TRUE(contains(r.err, message)) << r.err;
        }
    } else {
        EXPECT_TRUE(failed(r, c.exitCode, message));
    }
    if (c.timesOut) {
        EXPECT_LT(r.seconds, 10);
    }
    expectRowsUpTo(run.csv, c.h, c.lastRow);
}

INSTANTIATE_TEST_SUITE_P(FmusimReliability, FmusimFault,
                         ::testing::ValuesIn(faultRuns),
                         [](const ::testing::TestParamInfo<FaultRun>& info) {
                             return std::string(info.param.name);
                         });

TEST(FmusimReliability, CheckTimesOutInAnEndlessStep)
{
    const harness::Result r
        = fmusim("check " + fixture("hangingSpring") + " --timeout 1", 60);
    EXPECT_EQ(r.exitCode, 6) << r.out << r.err;
    EXPECT_LT(r.seconds, 10);
    EXPECT_TRUE(contains(r.out, "PASS initialization\n"))
        << r.out; // the checks before it are reported
    EXPECT_TRUE(
        contains(r.err,
                 "fmi2DoStep at t = 0 in FMU '" + fixture("hangingSpring")
                     + "', instance 'random' did not return within 1 s"))
        << r.err;
}

TEST(FmusimReliability, TimeOutIsANonNegativeNumber)
{
    for (const auto& [command, negative] : eachCommand("--timeout -1")) {
        EXPECT_EQ(negative.exitCode, 2) << command;
        EXPECT_TRUE(contains(
            negative.err, "timeout must be a non-negative number of seconds"))
            << negative.err;
    }
    for (const auto& [command, r] : eachCommand("--timeout soon"))
        EXPECT_EQ(r.exitCode, 2) << command;
    // 0, the default: no time-out.
    EXPECT_EQ(fmusim("run " + fixture("faultySpring")
                     + " --timeout 0 --stop-time 0.1")
                  .exitCode,
              0);
}

// The example's bungee with a fault in fmi2DoStep from t = 0.25 on
// (tests/customConnector/faultyBungee.c), run in a process of its own:
// fmusim goes on to say which call it was, ends with exit code 7 (6 for
// the time-out), and every row before the fault is on disk. Steps of 1/16
// s: rows 0 to 0.25, the step from 0.25 is the fault's. Of the faults of
// the channel between fmusim and that process, writes to descriptor 3 and
// closes of 0 to 63 miss it: the run ends as the bungee's does (exit code
// 0, all rows); writes to every socket the FMU finds, and a close of every
// descriptor, reach it and are named at once, in the call that did it.
struct Fault {
    const char* name;
    int exitCode;
    std::string message; // after "fmusim: ", before " in FMU"
};

const Fault faults[] = {
    {"segfault", 7,
     "the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep at t = 0.25"},
    {"divide-by-zero", 7,
     "the FMU crashed (SIGFPE, arithmetic exception) in fmi2DoStep at t = 0.25"},
    {"abort", 7, "the FMU crashed (SIGABRT, abort) in fmi2DoStep at t = 0.25"},
    {"exit", 7, "the FMU exited (status 0) in fmi2DoStep at t = 0.25"},
    {"hang", 6, "time-out: fmi2DoStep at t = 0.25"},
    {"write-fd3", 0, {}},
    {"close-fds", 0, {}},
    {"write-sockets", 7,
     "the channel to the FMU's process carried stray bytes (12 bytes that "
     "are not a message: magic word 0x61727473 where a message begins with "
     "0x31554d46) in fmi2DoStep at t = 0.25"},
    {"close-all-fds", 7,
     "the FMU closed its process's end of the channel in fmi2DoStep at t = "
     "0.25"}};

TEST(FmusimReliability, FaultsInAProcessOfTheirOwnAreReported)
{
    for (const Fault& f : faults) {
        const std::string fmu = fixture(std::string("faultyBungee-") + f.name);
        const std::string out = scratch("out.csv");
        const harness::Result r = fmusim(
            "run " + fmu
                + " --isolation process --timeout 1 --step-size 0.0625 "
                  "--stop-time 1 --output-file "
                + out,
            60);
        EXPECT_EQ(r.exitCode, f.exitCode) << f.name << "\n" << r.err;
        if (f.exitCode == 0) {
            expectRowsUpTo(out, 0.0625, 16);
            continue;
        }
        const std::string suffix = f.exitCode == 6
            ? " did not return within 1 s (--timeout)\n"
            : "\n";
        EXPECT_TRUE(contains(r.err,
                             "fmusim: " + f.message + " in FMU '" + fmu
                                 + "', instance 'bungee'" + suffix))
            << f.name << "\n"
            << r.err;
        expectRowsUpTo(out, 0.0625, 4);
    }
}

TEST(FmusimReliability, TwoBodyFaultInAProcessOfItsOwnIsReported)
{
    const std::string config = scratch("twobody.conf");
    harness::writeFile(config, "isolation = process\n");
    const harness::Result r = fmusim(
        "twobody " + fixture("faultyBungee-exit") + " --config " + config
            + " --step-size 0.0625 --stop-time 1 --B.position 0,0,2 "
              "--output-file "
            + scratch("out.csv"),
        60);
    EXPECT_TRUE(failed(r, 7,
                       "fmusim: the FMU exited (status 0) in "
                       "fmi2DoStep at t = 0.25 in FMU '"
                           + fixture("faultyBungee-exit")
                           + "', instance 'twobody'"));
}

// In fmusim's own process a crash takes fmusim with it, by the same
// signal, after the message naming the call.
TEST(FmusimReliability, CrashesInTheProcessAreNamed)
{
    for (const auto& [name, signal] :
         {std::pair<std::string, int> {"divide-by-zero", SIGFPE},
          {"abort", SIGABRT}}) {
        const harness::Result r = fmusim(
            "run " + fixture("faultyBungee-" + name)
            + " --step-size 0.0625 --output-file " + scratch("out.csv"));
        EXPECT_EQ(r.signal, signal) << name << "\n" << r.err;
        EXPECT_TRUE(contains(r.err, "fmusim: the FMU crashed (")
                    && contains(r.err,
                                ") in fmi2DoStep at t = 0.25 in FMU '"
                                    + fixture("faultyBungee-" + name) + "'"))
            << name << "\n"
            << r.err;
    }
}

// check gives each probe its own instance: in a process of its own, a
// probe whose FMU hangs fails, and the next probe goes on.
TEST(FmusimReliability, CheckInProcessesOfTheirOwnGoesOnAfterATimeOut)
{
    const harness::Result r = fmusim("check " + fixture("hangingSpring")
                                         + " --isolation process --timeout 0.5",
                                     120);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.out,
                         "FAIL random-kinematics: time-out: fmi2DoStep "
                         "at t = 0 in FMU '"
                             + fixture("hangingSpring")
                             + "', instance 'random' did not return "
                               "within 0.5 s (--timeout)"))
        << r.out;
    EXPECT_TRUE(contains(r.out, "failed\n")) << r.out; // it went to the end
}

TEST(FmusimReliability, IsolationIsNoneOrProcess)
{
    for (const auto& [command, r] : eachCommand("--isolation thread")) {
        EXPECT_EQ(r.exitCode, 2) << command;
        EXPECT_TRUE(contains(r.err, "isolation") && contains(r.err, "'thread'")
                    && contains(r.err, "none") && contains(r.err, "process"))
            << r.err;
    }
}

TEST(FmusimReliability, HelpDocumentsTheTimeOut)
{
    const harness::Result r = fmusim("--help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* part :
         {"--timeout SECONDS       end the run (exit code 6)",
          "[--timeout SECONDS]", "timeout (0, no limit) [s]",
          "6  time-out: a call into the FMU did not return",
          "7  the FMU crashed or exited in a call", "--isolation none|process",
          "isolation: none (default), or process"})
        EXPECT_TRUE(contains(r.out, part)) << part << "\n" << r.out;
}

} // namespace

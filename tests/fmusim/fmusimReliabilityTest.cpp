// fmusim against misbehaving FMUs (faultySpring: NaN outputs, a crash or an
// endless loop from a given time on; hangingSpring: every step hangs;
// faultyBungee-<fault>: the example's bungee that crashes, aborts, exits or
// hangs), in its own process and in one of the FMU's own (--isolation
// process): a clear message, a documented exit code, and every row before
// the fault on disk.
#include "fmusimTest.hpp"

#include <cmath>
#include <csignal>
#include <utility>

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

// Steps of 1/4 s, exact in binary: A.F[1] is NaN from the step at 0.5 on,
// so from the row for 0.75.
TEST(FmusimReliability, RunStopsAtANonFiniteOutput)
{
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim(
        "run " + fixture("faultySpring")
        + " --set nanTime=0.3 --step-size 0.25 --stop-time 2 --output-file "
        + out);
    EXPECT_TRUE(failed(r, 5,
                       "FMU '" + fixture("faultySpring")
                           + "', instance 'faultySpring': output 'A.F[1]' is "
                             "nan at t = 0.75, expected a finite number"));
    expectRowsUpTo(out, 0.25, 2);
}

TEST(FmusimReliability, TwoBodyStopsAtANonFiniteOutput)
{
    // Both bodies fixed: the NaN load moves nothing, only the check stops it.
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim(
        "twobody " + fixture("faultySpring")
        + " --set nanTime=0.3 --step-size 0.25 --stop-time 2 --B.position 1,0,0 --A.motion fixed --B.motion fixed"
          " --output-file "
        + out);
    EXPECT_TRUE(failed(
        r, 5,
        "FMU '" + fixture("faultySpring")
            + "', instance 'twobody': output 'A.F[1]' is nan at t = 0.75, expected a finite number"));
    expectRowsUpTo(out, 0.25, 2);
}

// A segmentation fault in fmi2DoStep at t = 0.75 with steps of 1/1024 s:
// fmusim dies of it, says where, and the 769 rows before are on disk (30 kB,
// more than an output buffer holds, and not a multiple of it).
TEST(FmusimReliability, RowsSurviveACrashInTheFmu)
{
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim(
        "run " + fixture("faultySpring")
        + " --set crashTime=0.75 --step-size 0.0009765625 --output-file "
        + out);
    EXPECT_EQ(r.signal, SIGSEGV) << "exit code " << r.exitCode << "\n" << r.err;
    EXPECT_TRUE(contains(
        r.err,
        "fmusim: the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep at t = 0.75 in FMU '"
            + fixture("faultySpring") + "', instance 'faultySpring'"))
        << r.err;
    expectRowsUpTo(out, 0.0009765625, 768);
}

// Two bodies joined by the spring, B released 0.1 m from its rest
// position: rows of moving bodies, longer ones.
TEST(FmusimReliability, RowsSurviveACrashInTwoBody)
{
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim(
        "twobody " + fixture("faultySpring")
        + " --set crashTime=0.75 --B.position 1.1,0,0 --step-size 0.00390625 --stop-time 1 --output-file "
        + out);
    EXPECT_EQ(r.signal, SIGSEGV) << "exit code " << r.exitCode << "\n" << r.err;
    expectRowsUpTo(out, 0.00390625, 192);
}

// fmi2DoStep at t = 0.75 never returns: --timeout 1 ends the run within a
// few seconds, with exit code 6, a message naming the call, and the rows
// before it on disk.
TEST(FmusimReliability, RunTimesOutInAnEndlessStep)
{
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim(
        "run " + fixture("faultySpring")
            + " --set hangTime=0.75 --step-size 0.00390625 --timeout 1 --output-file "
            + out,
        60);
    EXPECT_TRUE(failed(
        r, 6,
        "fmusim: time-out: fmi2DoStep at t = 0.75 in FMU '"
            + fixture("faultySpring")
            + "', instance 'faultySpring' did not return within 1 s (--timeout)"));
    EXPECT_LT(r.seconds, 10);
    expectRowsUpTo(out, 0.00390625, 192);
}

TEST(FmusimReliability, TwoBodyTimesOutInAnEndlessStep)
{
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim(
        "twobody " + fixture("faultySpring")
            + " --set hangTime=0.3 --B.position 1,0,0 --step-size 0.25 --stop-time 2 --timeout 0.5 --output-file "
            + out,
        60);
    EXPECT_TRUE(
        failed(r, 6,
               "fmi2DoStep at t = 0.5 in FMU '" + fixture("faultySpring")
                   + "', instance 'twobody' did not return within 0.5 s"));
    EXPECT_LT(r.seconds, 10);
    expectRowsUpTo(out, 0.25, 2);
}

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
    for (const char* command : {"run", "check", "twobody"}) {
        const harness::Result negative
            = fmusim(std::string(command) + " " + fixture("testSpring")
                     + " --timeout -1");
        EXPECT_EQ(negative.exitCode, 2) << command;
        EXPECT_TRUE(contains(
            negative.err, "timeout must be a non-negative number of seconds"))
            << negative.err;
        EXPECT_EQ(fmusim(std::string(command) + " " + fixture("testSpring")
                         + " --timeout soon")
                      .exitCode,
                  2)
            << command;
    }
    // 0, the default: no time-out.
    EXPECT_EQ(fmusim("run " + fixture("faultySpring")
                     + " --timeout 0 --stop-time 0.1")
                  .exitCode,
              0);
}

// The example's bungee with a fault in the first fmi2DoStep from t = 0.25
// on (tests/customConnector/faultyBungee.c), run in a process of its own:
// fmusim goes on to say which call it was, ends with exit code 7 (6 for
// the time-out), and every row before the fault is on disk. Steps of 1/16
// s: rows 0 to 0.25, the step from 0.25 is the fault's.
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
    {"hang", 6, "time-out: fmi2DoStep at t = 0.25"}};

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

// In fmusim's own process an FMU's exit(0) would end fmusim with status 0,
// a success: the importer's exit hook names the call and makes it 7.
TEST(FmusimReliability, ExitInTheFmuIsNamedAndNotASuccess)
{
    const std::string out = scratch("out.csv");
    const harness::Result r
        = fmusim("run " + fixture("faultyBungee-exit")
                 + " --step-size 0.0625 --output-file " + out);
    EXPECT_TRUE(failed(r, 7,
                       "fmusim: the FMU exited (status 0) in "
                       "fmi2DoStep at t = 0.25 in FMU '"
                           + fixture("faultyBungee-exit")
                           + "', instance 'bungee'\n"));
    expectRowsUpTo(out, 0.0625, 4);
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
    for (const char* command : {"run", "check", "twobody"}) {
        const harness::Result r
            = fmusim(std::string(command) + " " + fixture("testSpring")
                     + " --isolation thread");
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

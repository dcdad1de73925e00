// fmusim against misbehaving FMUs (faultySpring: NaN outputs, a crash or an
// endless loop from a given time on; hangingSpring: every step hangs): a
// clear message, a documented exit code, and every row before the fault on
// disk.
#include "fmusimHarness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>

namespace {

using harness::fixture;
using harness::fmusim;
using harness::scratch;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The rows of a CSV with communication points k h, k = 0..last.
void expectRowsUpTo(const std::string& csv, double h, int last)
{
    const harness::Table t = harness::readTable(csv);
    ASSERT_EQ(t.rows.size(), static_cast<std::size_t>(last + 1)) << csv;
    for (int k = 0; k <= last; ++k)
    {
        EXPECT_EQ(t.rows[k][0], k * h) << csv << " row " << k;
        for (const double value : t.rows[k]) EXPECT_TRUE(std::isfinite(value)) << csv << " row " << k;
    }
}

// Steps of 1/4 s, exact in binary: A.F[1] is NaN from the step at 0.5 on,
// so from the row for 0.75.
TEST(FmusimReliability, RunStopsAtANonFiniteOutput)
{
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim("run " + fixture("faultySpring") +
                                     " --set nanTime=0.3 --step-size 0.25 --stop-time 2 --output-file " + out);
    EXPECT_EQ(r.exitCode, 5) << r.err;
    EXPECT_TRUE(contains(r.err, "FMU '" + fixture("faultySpring") +
                                    "', instance 'faultySpring': output 'A.F[1]' is "
                                    "nan at t = 0.75, expected a finite number"))
        << r.err;
    expectRowsUpTo(out, 0.25, 2);
}

TEST(FmusimReliability, TwoBodyStopsAtANonFiniteOutput)
{
    // Both bodies fixed: the NaN load moves nothing, only the check stops it.
    const std::string out = scratch("out.csv");
    const harness::Result r =
        fmusim("twobody " + fixture("faultySpring") +
               " --set nanTime=0.3 --step-size 0.25 --stop-time 2 --B.position 1,0,0 --A.motion fixed --B.motion fixed"
               " --output-file " +
               out);
    EXPECT_EQ(r.exitCode, 5) << r.err;
    EXPECT_TRUE(
        contains(r.err, "FMU '" + fixture("faultySpring") +
                            "', instance 'twobody': output 'A.F[1]' is nan at t = 0.75, expected a finite number"))
        << r.err;
    expectRowsUpTo(out, 0.25, 2);
}

// A segmentation fault in fmi2DoStep at t = 0.75 with steps of 1/1024 s:
// fmusim dies of it, says where, and the 769 rows before are on disk (30 kB,
// more than an output buffer holds, and not a multiple of it).
TEST(FmusimReliability, RowsSurviveACrashInTheFmu)
{
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim("run " + fixture("faultySpring") +
                                     " --set crashTime=0.75 --step-size 0.0009765625 --output-file " + out);
    EXPECT_EQ(r.signal, SIGSEGV) << "exit code " << r.exitCode << "\n" << r.err;
    EXPECT_TRUE(
        contains(r.err, "fmusim: the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep at t = 0.75 in FMU '" +
                            fixture("faultySpring") + "', instance 'faultySpring'"))
        << r.err;
    expectRowsUpTo(out, 0.0009765625, 768);
}

// Two bodies joined by the spring, B released 0.1 m from its rest
// position: rows of moving bodies, longer ones.
TEST(FmusimReliability, RowsSurviveACrashInTwoBody)
{
    const std::string out = scratch("out.csv");
    const harness::Result r =
        fmusim("twobody " + fixture("faultySpring") +
               " --set crashTime=0.75 --B.position 1.1,0,0 --step-size 0.00390625 --stop-time 1 --output-file " + out);
    EXPECT_EQ(r.signal, SIGSEGV) << "exit code " << r.exitCode << "\n" << r.err;
    expectRowsUpTo(out, 0.00390625, 192);
}

}  // namespace

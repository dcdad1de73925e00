// `fmusim run` on the first-order lag fixture (T dy/dt = u - y, exact steps
// for piecewise-linear input): analytic solutions, input tables, parameter
// files, and the exit code and message of each failure class.
#include "fmusimTest.hpp"

#include <cmath>

namespace {

using namespace harness;

// `fmusim run` of the first-order lag with the input table in, holding text
Result runWithInput(const std::string& in, const std::string& text)
{
    writeFile(in, text);
    return fmusim("run " + fixture("firstOrderLag") + " --input-file " + in);
}

TEST(FmusimRun, StepResponseMatchesTheAnalyticSolution)
{
    const std::string out = scratch("out.csv");
    const harness::Result r = fmusim(
        "run " + fixture("firstOrderLag")
        + " --set timeConstant=0.5 --set u=1 --stop-time 2 --step-size 0.01 --output-file "
        + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const harness::Table t = harness::readTable(out);
    ASSERT_EQ(t.names, (std::vector<std::string> {"time", "y", "stepCount"}));
    ASSERT_EQ(t.rows.size(), 201u);
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const double time = t.rows[i][0];
        EXPECT_NEAR(time, 0.01 * i, 1e-14); // t0 + k h, not a running sum
        // Exact steps, 17 significant digits in the CSV: round-off only.
        EXPECT_NEAR(t.rows[i][1], 1 - std::exp(-time / 0.5), 1e-13)
            << "t = " << time;
        EXPECT_EQ(t.rows[i][2], static_cast<double>(i));
    }
}

TEST(FmusimRun, DefaultExperimentAndStandardOutput)
{
    const harness::Result r
        = fmusim("run " + fixture("firstOrderLag") + " --output-variables y");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const harness::Table t = harness::parseTable(r.out);
    ASSERT_EQ(t.rows.size(),
              301u); // DefaultExperiment: 0 to 3 s in steps of 0.01 s
    EXPECT_DOUBLE_EQ(t.rows.back()[0], 3.0);
}

TEST(FmusimRun, InputTableIsInterpolatedLinearly)
{
    // u: ramp 0 -> 2 over [0, 1], then held at 2; rows only at 0, 1, 3, so
    // every intermediate communication point needs interpolation. With the
    // ramp breaks on communication points the lag's exact steps give the
    // analytic solution: y = 2 (t - T + T e^(-t/T)) on [0, 1] (T = 1), then
    // y = 2 + (y(1) - 2) e^(-(t - 1)).
    const std::string in = scratch("in.csv"), out = scratch("out.csv");
    harness::writeFile(in, "# ramp then hold\ntime, u\n0, 0\n1, 2\n\n3, 2\n");
    const harness::Result r
        = fmusim("run " + fixture("firstOrderLag") + " --input-file " + in
                 + " --step-size 0.1 --stop-time 2.5" + " --output-file " + out
                 + " --output-variables u,y");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const harness::Table t = harness::readTable(out);
    ASSERT_EQ(t.rows.size(), 26u);
    const double y1 = 2 * std::exp(-1.0);
    for (const std::vector<double>& row : t.rows) {
        const double time = row[0];
        const double u = time <= 1 ? 2 * time : 2.0;
        const double y = time <= 1 ? 2 * (time - 1 + std::exp(-time))
                                   : 2 + (y1 - 2) * std::exp(-(time - 1));
        EXPECT_NEAR(row[1], u, 1e-14)
            << "t = " << time; // interpolated input echoed by the FMU
        EXPECT_NEAR(row[2], y, 1e-13)
            << "t = " << time; // exact steps: round-off only
    }
}

TEST(FmusimRun, BooleanInputTakesThePreviousRow)
{
    // hold switches on at t = 0.5: y must stay at y(0.5) from then on.
    const std::string in = scratch("in.csv"), out = scratch("out.csv");
    harness::writeFile(in, "time,u,hold\n0,1,0\n0.5,1,1\n");
    const harness::Result r
        = fmusim("run " + fixture("firstOrderLag") + " --input-file " + in
                 + " --step-size 0.1 --stop-time 1 --output-file " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<double> y = harness::readTable(out).values("y");
    ASSERT_EQ(y.size(), 11u);
    // The step ending at 0.5 is the first one made with hold = true.
    EXPECT_NEAR(y[4], 1 - std::exp(-0.4), 1e-14);
    for (std::size_t i = 5; i < y.size(); ++i)
        EXPECT_EQ(y[i], y[4]);
}

TEST(FmusimRun, ParameterFileAndSetOverride)
{
    const std::string params = scratch("params.txt"), out = scratch("out.csv");
    harness::writeFile(
        params,
        "# lag parameters\ntimeConstant = 0.25   # s\n\ninitialValue = 3\nlabel = from file\n");
    const harness::Result r = fmusim(
        "run " + fixture("firstOrderLag") + " --parameters " + params
        + " --set initialValue=2 --stop-time 1 --step-size 0.5 --output-file "
        + out + " --output-variables y,label --logging");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const harness::Table t = harness::readTable(out);
    EXPECT_NEAR(t.rows[2][1], 2 * std::exp(-1 / 0.25),
                1e-15); // u = 0: pure decay from 2
    EXPECT_TRUE(
        contains(r.err, "from file: timeConstant = 0.25 s, initialValue = 2"))
        << r.err;
}

TEST(FmusimRunErrors, BadRowInTheInputTable)
{
    const std::string in = scratch("in.csv");
    const harness::Result r = runWithInput(in, "time,u\n0,0\n1,2,3\n");
    EXPECT_TRUE(failed(r, 4, in + ":3: expected 2 values, found 3"));
    EXPECT_TRUE(r.out.empty()) << "no output for a run that never started";

    const harness::Result notNumber = runWithInput(in, "time,u\n0,0\n1,abc\n");
    EXPECT_TRUE(failed(notNumber, 4,
                       in + ":3: 'abc' in column 2 is not a finite number"));

    const harness::Result backwards = runWithInput(in, "time,u\n1,0\n0,2\n");
    EXPECT_TRUE(
        failed(backwards, 4,
               in + ":3: time 0 is before the time of the previous row"));
}

TEST(FmusimRunErrors, MissingVariableInTheInputTable)
{
    const std::string in = scratch("in.csv");
    const harness::Result r = runWithInput(in, "time,u,windSpeed\n0,0,1\n");
    EXPECT_TRUE(failed(r, 4,
                       in + ":1: column 'windSpeed': FMU '"
                           + fixture("firstOrderLag")
                           + "' has no variable 'windSpeed'"));

    const harness::Result output = runWithInput(in, "time,y\n0,0\n");
    EXPECT_TRUE(failed(output, 4, "column 'y': the variable is not an input"));
}

TEST(FmusimRunErrors, UnknownParameterInAFile)
{
    const std::string params = scratch("params.txt");
    harness::writeFile(params, "timeConstant = 1\ngain = 2\n");
    const harness::Result r
        = fmusim("run " + fixture("firstOrderLag") + " --parameters " + params);
    EXPECT_TRUE(failed(r, 4,
                       params + ":2: FMU '" + fixture("firstOrderLag")
                           + "' has no variable 'gain'"));
}

TEST(FmusimRunErrors, MalformedFmu)
{
    const harness::Result r = fmusim("run " + fixture("notAZip"));
    EXPECT_TRUE(failed(r, 3,
                       "FMU '" + fixture("notAZip")
                           + "' cannot be opened as a zip archive"));

    const harness::Result guid = fmusim("run " + fixture("guidMismatch"));
    EXPECT_TRUE(failed(guid, 3, "fmi2Instantiate failed"));
}

TEST(FmusimRunErrors, UsageErrors)
{
    EXPECT_EQ(fmusim("").exitCode, 2);
    EXPECT_EQ(fmusim("simulate x.fmu").exitCode, 2);
    const harness::Result option
        = fmusim("run " + fixture("firstOrderLag") + " --stop 3");
    EXPECT_TRUE(failed(option, 2, "unknown option --stop"));
    const harness::Result value
        = fmusim("run " + fixture("firstOrderLag") + " --step-size fast");
    EXPECT_TRUE(failed(value, 2, "--step-size: 'fast' is not a finite number"));
    const harness::Result set
        = fmusim("run " + fixture("firstOrderLag") + " --set y=1");
    EXPECT_TRUE(failed(
        set, 2,
        "--set: variable 'y' cannot be set before initialization: it is neither a parameter nor an input and has no start value"));
}

TEST(FmusimRunErrors, FailingFmuCallIsASimulationError)
{
    const harness::Result r
        = fmusim("run " + fixture("firstOrderLag") + " --set timeConstant=-1");
    EXPECT_TRUE(failed(r, 5, "fmi2ExitInitializationMode failed"));
    EXPECT_TRUE(
        contains(r.err, "timeConstant = -1 s must be positive and finite"))
        << r.err;
}

TEST(FmusimHelp, ListsSubcommandsAndExitCodes)
{
    const harness::Result r = fmusim("--help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* part : {"fmusim run", "fmusim check", "fmusim twobody",
                             "Exit codes", "5  simulation error"})
        EXPECT_TRUE(contains(r.out, part)) << part;
}

} // namespace

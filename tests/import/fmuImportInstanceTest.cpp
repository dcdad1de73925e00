// Driving instances of the first-order lag fixture (T dy/dt = u - y, exact
// steps): values of every type, stepping against the analytic solution,
// FMU state, error reporting and logger forwarding.
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

using fixtures::fmuPath;

struct LogEntry {
    std::string instance;
    int status;
    std::string category;
    std::string message;
};

// In this process and in a child process (Isolation::process): the same
// results, messages and errors.
class LagInstance : public ::testing::TestWithParam<fmuImport::Isolation> {
protected:
    fmuImport::Fmu fmu {fmuPath("firstOrderLag"), {GetParam(), 0, ""}};
    std::vector<LogEntry> log;

    unsigned int vr(const std::string& name) const
    {
        return fmu.variable(name).valueReference;
    }

    fmuImport::Logger recorder()
    {
        return [this](const std::string& instance, int status,
                      const std::string& category, const std::string& message) {
            log.push_back({instance, status, category, message});
        };
    }

    // An initialised instance with the given time constant and a constant
    // input u, from t = 0.
    fmuImport::Instance started(double T, double u, bool loggingOn = false)
    {
        fmuImport::Instance lag(fmu, "lag1", recorder(), loggingOn);
        lag.setupExperiment(0.0);
        lag.enterInitializationMode();
        lag.setReal({vr("timeConstant"), vr("u")}, {T, u});
        lag.exitInitializationMode();
        return lag;
    }

    double y(fmuImport::Instance& lag) { return lag.getReal({vr("y")})[0]; }
};

TEST_P(LagInstance, StepResponseMatchesTheAnalyticSolution)
{
    const double T = 0.5, h = 0.01;
    fmuImport::Instance lag = started(T, 1.0);
    for (int n = 0; n < 200; ++n) {
        lag.doStep(n * h, h);
        const double t = (n + 1) * h;
        // Each step is exact; only round-off of about 1e-16 per step adds up.
        EXPECT_NEAR(y(lag), 1.0 - std::exp(-t / T), 1e-13) << "t = " << t;
    }
    EXPECT_DOUBLE_EQ(lag.time(), 200 * h);
    EXPECT_EQ(lag.getInteger({vr("stepCount")})[0], 200);
}

TEST_P(LagInstance, BooleanAndStringValues)
{
    fmuImport::Instance lag(fmu, "lag1", recorder(), true);
    lag.setupExperiment(0.0);
    lag.enterInitializationMode();
    lag.setString({vr("label")}, {"ramp-test"});
    EXPECT_EQ(lag.getString({vr("label")})[0], "ramp-test");
    lag.setReal({vr("u")}, {2.0});
    lag.exitInitializationMode();
    lag.setBoolean({vr("hold")}, {true});
    EXPECT_EQ(lag.getBoolean({vr("hold")}), std::vector<bool> {true});
    lag.doStep(0.0, 0.1);
    EXPECT_EQ(y(lag), 0.0); // held: y is not touched at all
    lag.setBoolean({vr("hold")}, {false});
    lag.doStep(0.1, 0.1);
    EXPECT_GT(y(lag), 0.0);
    lag.setInteger({vr("stepCount")}, {40});
    EXPECT_EQ(lag.getInteger({vr("stepCount")})[0], 40);
}

TEST_P(LagInstance, StateRoundTripRestoresValuesAndTime)
{
    fmuImport::Instance lag = started(0.3, 1.0);
    lag.doStep(0.0, 0.1);
    fmuImport::Instance::State saved = lag.getState();
    ASSERT_TRUE(saved.valid());
    const double ySaved = y(lag);

    lag.setReal({vr("u")}, {-4.0});
    lag.doStep(0.1, 0.1);
    const double yAfter = y(lag);
    EXPECT_NE(yAfter, ySaved);

    lag.setState(saved);
    EXPECT_EQ(y(lag), ySaved); // a copy of the values: bit for bit
    EXPECT_DOUBLE_EQ(lag.time(), 0.1);
    EXPECT_EQ(lag.getInteger({vr("stepCount")})[0], 1);
    lag.setReal({vr("u")}, {-4.0});
    lag.doStep(0.1, 0.1);
    EXPECT_EQ(y(lag), yAfter); // the same step from the same state: identical

    const std::vector<char> bytes = lag.serializeState(saved);
    EXPECT_FALSE(bytes.empty());
    fmuImport::Instance::State restored = lag.deserializeState(bytes);
    lag.setState(restored);
    EXPECT_EQ(y(lag), ySaved);
    EXPECT_EQ(lag.getInteger({vr("stepCount")})[0], 1);
}

TEST_P(LagInstance, StateSavedAgainOverwritesTheSavedOne)
{
    fmuImport::Instance lag = started(0.3, 1.0);
    fmuImport::Instance::State saved;
    lag.getState(saved); // empty: a new state
    ASSERT_TRUE(saved.valid());
    lag.doStep(0.0, 0.1);
    lag.getState(saved); // the same state, overwritten
    const double ySaved = y(lag);

    lag.setReal({vr("u")}, {-4.0});
    lag.doStep(0.1, 0.1);
    lag.setState(saved);
    EXPECT_EQ(y(lag), ySaved);
    EXPECT_DOUBLE_EQ(lag.time(), 0.1);
    EXPECT_EQ(lag.getInteger({vr("stepCount")})[0], 1);

    // A state of another instance is replaced by one of this instance
    fmuImport::Instance other = started(0.3, 1.0);
    other.getState(saved);
    EXPECT_NO_THROW(other.setState(saved));
    EXPECT_THROW(lag.setState(saved), fmuImport::Error);
}

TEST_P(LagInstance, SerializedStateMovesToAnotherInstance)
{
    fmuImport::Instance first = started(0.3, 1.0);
    first.doStep(0.0, 0.25);
    const std::vector<char> bytes = first.serializeState(first.getState());

    fmuImport::Instance second = started(0.3, 0.0);
    second.setState(second.deserializeState(bytes));
    EXPECT_EQ(y(second), y(first));
    first.doStep(0.25, 0.25);
    second.doStep(0.25, 0.25);
    EXPECT_EQ(y(second), y(first));
}

TEST_P(LagInstance, StateOfAnotherInstanceIsRefused)
{
    fmuImport::Instance first = started(0.3, 1.0);
    fmuImport::Instance second = started(0.3, 1.0);
    const fmuImport::Instance::State s = first.getState();
    EXPECT_THROW(second.setState(s), fmuImport::Error);
    EXPECT_THROW(second.setState(fmuImport::Instance::State()),
                 fmuImport::Error);
}

TEST_P(LagInstance, LoggerReceivesFormattedMessages)
{
    fmuImport::Instance lag = started(0.5, 1.0, true);
    ASSERT_EQ(log.size(), 1u);
    EXPECT_EQ(log[0].instance, "lag1");
    EXPECT_EQ(log[0].status, 0);
    EXPECT_EQ(log[0].category, "logEvents");
    EXPECT_EQ(log[0].message, "lag: timeConstant = 0.5 s, initialValue = 0");
}

TEST_P(LagInstance, FailedCallNamesFunctionFmuInstanceAndTheFmuMessage)
{
    fmuImport::Instance lag(fmu, "lag1", recorder());
    lag.setupExperiment(0.0);
    lag.enterInitializationMode();
    lag.setReal({vr("timeConstant")}, {-1.0});
    try {
        lag.exitInitializationMode();
        FAIL() << "a negative time constant was accepted";
    } catch (const fmuImport::Error& e) {
        EXPECT_EQ(
            std::string(e.what()),
            "fmi2ExitInitializationMode failed in FMU '"
                + fmuPath("firstOrderLag")
                + "', instance 'lag1' (fmi2Error): timeConstant = -1 s must be positive "
                  "and finite");
    }
    ASSERT_FALSE(log.empty());
    EXPECT_EQ(log.back().status, 3);
    EXPECT_EQ(log.back().category, "logStatusError");
}

TEST_P(LagInstance, DoStepFailureNamesTheTime)
{
    fmuImport::Instance lag = started(0.5, 1.0);
    lag.doStep(0.0, 0.1);
    try {
        lag.doStep(0.1, -0.1);
        FAIL() << "a negative step was accepted";
    } catch (const fmuImport::Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(
                      "fmi2DoStep failed at t = 0.10000000000000001 in FMU '"
                          + fmuPath("firstOrderLag") + "', instance 'lag1'",
                      0),
                  0u)
            << message;
        EXPECT_NE(message.find("invalid step from t = 0.1 with h = -0.1"),
                  std::string::npos)
            << message;
    }
}

TEST_P(LagInstance, NonFiniteInputIsAnError)
{
    fmuImport::Instance lag = started(0.5, 1.0);
    try {
        // In a child process the error of fmi2SetReal comes with the next
        // call that returns something
        lag.setReal({vr("u")}, {std::nan("")});
        lag.getReal({vr("y")});
        FAIL() << "NaN input was accepted";
    } catch (const fmuImport::Error& e) {
        EXPECT_NE(std::string(e.what()).find("fmi2SetReal failed at t = 0"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find(
                      "u (value reference 2) set to the non-finite value nan"),
                  std::string::npos)
            << e.what();
    }
}

TEST_P(LagInstance, MismatchedSizesAreRefusedBeforeTheCall)
{
    fmuImport::Instance lag = started(0.5, 1.0);
    EXPECT_THROW(lag.setReal({vr("u"), vr("timeConstant")}, {1.0}),
                 fmuImport::Error);
}

TEST_P(LagInstance, InstancesAreIndependent)
{
    fmuImport::Instance a = started(0.5, 1.0);
    fmuImport::Instance b = started(2.0, 1.0);
    a.doStep(0.0, 1.0);
    b.doStep(0.0, 1.0);
    // Exact steps of the same form: the analytic values to round-off.
    EXPECT_NEAR(y(a), 1.0 - std::exp(-2.0), 1e-15);
    EXPECT_NEAR(y(b), 1.0 - std::exp(-0.5), 1e-15);
}

std::string
isolationName(const ::testing::TestParamInfo<fmuImport::Isolation>& info)
{
    return info.param == fmuImport::Isolation::none ? "inProcess"
                                                    : "childProcess";
}

INSTANTIATE_TEST_SUITE_P(Isolation, LagInstance,
                         ::testing::Values(fmuImport::Isolation::none,
                                           fmuImport::Isolation::process),
                         isolationName);

TEST(InstanceLifetime, GuidMismatchFailsInstantiate)
{
    const fmuImport::Fmu fmu(fmuPath("guidMismatch"));
    try {
        fmuImport::Instance lag(fmu, "lag1",
                                [](const std::string&, int, const std::string&,
                                   const std::string&) {});
        FAIL() << "instantiated with a wrong GUID";
    } catch (const fmuImport::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("fmi2Instantiate failed in FMU '"
                               + fmuPath("guidMismatch")
                               + "', instance 'lag1'"),
                  std::string::npos)
            << message;
        EXPECT_NE(
            message.find(
                "GUID '{00000000-0000-0000-0000-000000000000}' does not match"),
            std::string::npos)
            << message;
    }
}

TEST(InstanceLifetime, InstanceKeepsTheFmuLoadedAndCleansUpLast)
{
    fixtures::PrivateTmpDir tmp;
    std::string directory;
    {
        std::unique_ptr<fmuImport::Instance> lag;
        {
            const fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
            directory = fmu.unpackDirectory();
            lag.reset(new fmuImport::Instance(fmu, "lag1"));
        }
        EXPECT_TRUE(std::filesystem::exists(directory));
        lag->setupExperiment(0.0);
        lag->enterInitializationMode();
        lag->exitInitializationMode();
        lag->doStep(0.0, 0.1);
    }
    EXPECT_FALSE(std::filesystem::exists(directory));
    EXPECT_TRUE(tmp.contents().empty());
}

} // namespace

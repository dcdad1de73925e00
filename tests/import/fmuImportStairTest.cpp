// The end of a simulation as FMI 2.0 has it (section 4.2.3), on the stair
// fixture: a co-simulation-only FMU (no model-exchange functions) whose
// counter goes up every second, which asks to end the simulation at endTime
// (fmi2Discard with fmi2Terminated) and discards every step from
// discardTime on (fmi2Discard alone).
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

namespace {

using fixtures::fmuPath;
using Result = fmuImport::Instance::StepResult;

// In this process and in a child process (Isolation::process)
struct Stair : ::testing::TestWithParam<fmuImport::Isolation> {
    fmuImport::Fmu fmu {
        fmuPath("stair"),
        {GetParam(), 0, ""}}; // loads: only common and CS functions needed
    fmuImport::Instance instance {
        fmu, "stair",
        [](const std::string&, int, const std::string&, const std::string&) {}};

    void start(double discardTime = 1e300)
    {
        instance.setupExperiment(0.0);
        instance.setReal({fmu.variable("discardTime").valueReference},
                         {discardTime});
        instance.enterInitializationMode();
        instance.exitInitializationMode();
    }
    int counter()
    {
        return instance.getInteger({fmu.variable("counter").valueReference})[0];
    }
};

TEST_P(Stair, CoSimulationOnlyBinaryLoads)
{
    start();
    EXPECT_EQ(instance.tryDoStep(0.0, 1.0), Result::completed);
    EXPECT_EQ(counter(), 2);
}

TEST_P(Stair, AskingToTerminateIsNotAnError)
{
    start();
    const double h = 0.5;
    double t = 0.0;
    Result result = Result::completed;
    while ((result = instance.tryDoStep(t, h)) == Result::completed)
        t += h;
    EXPECT_EQ(result, Result::terminated);
    EXPECT_EQ(instance.lastMessage(),
              "fmi2DoStep at t = 10: the stair ends at t = 10");
    EXPECT_EQ(t, 10.0); // the step from 10 would pass endTime
    EXPECT_EQ(instance.time(), 10.0);
    EXPECT_EQ(instance.lastSuccessfulTime(), 10.0);
    EXPECT_EQ(counter(), 11); // outputs of the last successful time
}

TEST_P(Stair, DiscardWithoutTerminating)
{
    start(0.75);
    EXPECT_EQ(instance.tryDoStep(0.0, 0.5), Result::completed);
    EXPECT_EQ(instance.tryDoStep(0.5, 0.5), Result::completed);
    EXPECT_EQ(instance.tryDoStep(1.0, 0.5), Result::discarded);
    EXPECT_EQ(instance.lastSuccessfulTime(), 1.0);
    EXPECT_NE(
        instance.lastMessage().find("no step from t >= discardTime = 0.75"),
        std::string::npos)
        << instance.lastMessage();
    // doStep keeps treating a discarded step as an error
    try {
        instance.doStep(1.0, 0.5);
        ADD_FAILURE() << "doStep did not throw on fmi2Discard";
    } catch (const fmuImport::Error& e) {
        EXPECT_NE(std::string(e.what()).find("fmi2DoStep failed at t = 1"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("fmi2Discard"), std::string::npos)
            << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Isolation, Stair,
    ::testing::Values(fmuImport::Isolation::none,
                      fmuImport::Isolation::process),
    [](const ::testing::TestParamInfo<fmuImport::Isolation>& info) {
        return std::string(info.param == fmuImport::Isolation::none
                               ? "inProcess"
                               : "childProcess");
    });

} // namespace

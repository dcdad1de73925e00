// linearSpring.fmu against the law library: outputs equal the law's values,
// bad parameters are named at fmi2ExitInitializationMode, the zero-length
// limit and overflow.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ConnectorInputs.hpp"
#include "linearSpring/LinearSpring.hpp"

namespace {

using namespace fmuTest;

connectors::LinearSpringParameters springParameters()
{
    auto p = genericallyAttached<connectors::LinearSpringParameters>();
    p.stiffness = 250.0;
    p.restLength = 0.7;
    p.damping = 15.0;
    return p;
}

TEST(LinearSpringFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("linearSpring");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(genericParameters(fmu)), fmi2OK)
        << in.lastMessage();
    const connectors::LinearSpring law(springParameters());
    ASSERT_EQ(in.set(inputs(genericA(), genericB())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.01, fmi2True), fmi2OK);
    expectOutputs(in, law.evaluate(genericA(), genericB()));
    // A second configuration, read without a step (direct feedthrough).
    const BodyKinematics A
        = kinematics(Vector3(-1, 0.5, 0.2), 2.0, Vector3(0, 1, 0),
                     Vector3(0, 0, 1), Vector3(1, 0, 0));
    ASSERT_EQ(in.set(inputs(A, genericA())), fmi2OK);
    expectOutputs(in, law.evaluate(A, genericA()));
}

TEST(LinearSpringFmu, BadParametersAreNamedAtExitInitializationMode)
{
    LoadedFmu fmu("linearSpring");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<std::pair<std::pair<std::string, double>, std::string>>
        cases = {
            {{"stiffness", -5.0},
             "parameter stiffness = -5 N/m is out of range "
             "(allowed: finite and >= 0)"},
            {{"restLength", -1.0},
             "parameter restLength = -1 m is out of range "
             "(allowed: finite and >= 0)"},
            {{"damping", -2.0},
             "parameter damping = -2 N.s/m is out of range "
             "(allowed: finite and >= 0)"},
            {{"A.p[3]", nan},
             "parameter A.p[3] = nan m is out of range (allowed: finite)"},
        };
    for (const auto& [parameter, message] : cases) {
        Instance in(fmu);
        EXPECT_EQ(in.initialize({parameter}), fmi2Error);
        EXPECT_EQ(in.lastMessage(),
                  "fmi2ExitInitializationMode: linearSpring: " + message);
        EXPECT_EQ(in.log.back().category, "logStatusError");
        EXPECT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2Error);
    }
}

TEST(LinearSpringFmu, ZeroLengthLimit)
{
    LoadedFmu fmu("linearSpring");
    // B.p (start value (1, 0, 0)) on A.p (start value the origin)
    const std::map<std::string, double> coincident = {{"B.r[1]", -1.0}};
    {
        // restLength > 0 (start value 1 m): the force direction is undefined.
        Instance in(fmu);
        ASSERT_EQ(in.initialize({}), fmi2OK);
        ASSERT_EQ(in.set(coincident), fmi2OK);
        EXPECT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2Error);
        EXPECT_EQ(in.lastMessage(),
                  "fmi2DoStep: linearSpring: length 0 m is below 1e-12 m "
                  "with restLength = 1 m > 0: the spring force "
                  "direction is undefined");
    }
    {
        // restLength = 0: a well-defined zero force.
        Instance in(fmu);
        ASSERT_EQ(in.initialize({{"restLength", 0.0}}), fmi2OK);
        ASSERT_EQ(in.set(coincident), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK);
        std::vector<double> out;
        ASSERT_EQ(in.get(connectorOutputs(), out), fmi2OK);
        for (const double v : out) {
            EXPECT_EQ(v, 0.0);
        }
    }
}

TEST(LinearSpringFmu, OverflowIsAnErrorNotAnInfinity)
{
    LoadedFmu fmu("linearSpring");
    Instance in(fmu);
    ASSERT_EQ(in.initialize({{"stiffness", 1e300}, {"restLength", 0.0}}),
              fmi2OK);
    ASSERT_EQ(in.set({{"B.r[1]", 1e300}}), fmi2OK);
    std::vector<double> out;
    EXPECT_EQ(in.get(connectorOutputs(), out), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2GetReal: linearSpring: output A.F[1] = inf is not "
              "finite (inputs or parameters too large)");
}

} // namespace

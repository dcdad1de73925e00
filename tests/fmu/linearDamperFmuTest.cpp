// linearDamper.fmu against the law library: outputs equal the law's
// values, a bad damping is named at fmi2ExitInitializationMode.
#include <gtest/gtest.h>

#include "ConnectorInputs.hpp"
#include "linearDamper/LinearDamper.hpp"

namespace {

using namespace fmuTest;

TEST(LinearDamperFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("linearDamper");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(genericParameters(fmu)), fmi2OK)
        << in.lastMessage();
    // A.p, B.p and damping as in genericParameters
    connectors::LinearDamperParameters p;
    p.p_AoP_A = Vector3(0.1, -0.2, 0.3);
    p.p_BoQ_B = Vector3(-0.4, 0.05, 0.2);
    p.damping = 15.0;
    const connectors::LinearDamper law(p);
    ASSERT_EQ(in.set(inputs(genericA(), genericB())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.01, fmi2True), fmi2OK);
    expectOutputs(in, law.evaluate(genericA(), genericB()));
    ASSERT_EQ(in.set(inputs(genericB(), genericA())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.01, 0.02, fmi2True), fmi2OK);
    expectOutputs(in, law.evaluate(genericB(), genericA()));
}

TEST(LinearDamperFmu, NegativeDampingIsNamedAtExitInitializationMode)
{
    LoadedFmu fmu("linearDamper");
    Instance in(fmu);
    EXPECT_EQ(in.initialize({{"damping", -0.5}}), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2ExitInitializationMode: linearDamper: parameter "
              "damping = -0.5 N.s/m is out of range (allowed: finite "
              "and >= 0)");
}

} // namespace

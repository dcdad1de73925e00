// rotationalDamper.fmu against the law library: outputs equal the law's
// values, a bad damping is named at fmi2ExitInitializationMode.
#include <gtest/gtest.h>

#include "ConnectorInputs.hpp"
#include "rotationalDamper/RotationalDamper.hpp"

namespace {

using namespace fmuTest;

TEST(RotationalDamperFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("rotationalDamper");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(genericParameters(fmu)), fmi2OK)
        << in.lastMessage();
    // A.p, B.p and damping as in genericParameters
    auto p = genericallyAttached<connectors::RotationalDamperParameters>();
    p.damping = 15.0;
    const connectors::RotationalDamper law(p);
    ASSERT_NO_FATAL_FAILURE(stepBothWays(
        fmu, in, [&](const BodyKinematics& A, const BodyKinematics& B) {
            expectOutputs(in, law.evaluate(A, B));
        }));
}

TEST(RotationalDamperFmu, NegativeDampingIsNamedAtExitInitializationMode)
{
    LoadedFmu fmu("rotationalDamper");
    expectInitializationRefused(
        fmu, {{"damping", -0.5}},
        "fmi2ExitInitializationMode: rotationalDamper: parameter damping = -0.5 "
        "N.m.s/rad is out of range (allowed: finite and >= 0)");
}

} // namespace

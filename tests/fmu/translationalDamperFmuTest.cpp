// translationalDamper.fmu against the law library: outputs equal the law's
// values, a bad damping is named at fmi2ExitInitializationMode.
#include <gtest/gtest.h>

#include "ConnectorInputs.hpp"
#include "translationalDamper/TranslationalDamper.hpp"

namespace {

using namespace fmuTest;

TEST(TranslationalDamperFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("translationalDamper");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(genericParameters(fmu)), fmi2OK)
        << in.lastMessage();
    // A.p, B.p and damping as in genericParameters
    auto p = genericallyAttached<connectors::TranslationalDamperParameters>();
    p.damping = 15.0;
    const connectors::TranslationalDamper law(p);
    ASSERT_NO_FATAL_FAILURE(stepBothWays(
        fmu, in, [&](const BodyKinematics& A, const BodyKinematics& B) {
            expectOutputs(in, law.evaluate(A, B));
        }));
}

TEST(TranslationalDamperFmu, NegativeDampingIsNamedAtExitInitializationMode)
{
    LoadedFmu fmu("translationalDamper");
    expectInitializationRefused(
        fmu, {{"damping", -0.5}},
        "fmi2ExitInitializationMode: translationalDamper: parameter damping = -0.5 "
        "N.s/m is out of range (allowed: finite and >= 0)");
}

} // namespace

// sphericalAngularSpring.fmu against the law library: outputs equal the
// law's (a turned reference orientation), a referenceOrientation that is no
// rotation is named at fmi2ExitInitializationMode.
#include <gtest/gtest.h>

#include "ConnectorInputs.hpp"
#include "sphericalAngularSpring/SphericalAngularSpring.hpp"

namespace {

using namespace fmuTest;

TEST(SphericalAngularSpringFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("sphericalAngularSpring");
    Instance in(fmu);
    std::map<std::string, double> parameters = genericParameters(fmu);
    auto p
        = genericallyAttached<connectors::SphericalAngularSpringParameters>();
    p.R_BA0 = Eigen::AngleAxisd(0.4, Vector3(1, 2, -1).normalized())
                  .toRotationMatrix();
    p.stiffness = 250.0; // genericParameters'
    p.damping = 15.0;
    addMatrix(parameters, "referenceOrientation", p.R_BA0);
    ASSERT_EQ(in.initialize(parameters), fmi2OK) << in.lastMessage();
    const connectors::SphericalAngularSpring law(p);
    ASSERT_NO_FATAL_FAILURE(stepBothWays(
        fmu, in, [&](const BodyKinematics& A, const BodyKinematics& B) {
            expectOutputs(in, law.evaluate(A, B));
        }));
}

TEST(SphericalAngularSpringFmu, NoRotationIsNamedAtExitInitializationMode)
{
    LoadedFmu fmu("sphericalAngularSpring");
    expectInitializationRefused(
        fmu, {{"referenceOrientation[1,1]", 0.0}},
        "fmi2ExitInitializationMode: sphericalAngularSpring: parameter "
        "referenceOrientation is not a rotation tensor: "
        "|referenceOrientation| - sqrt(3) = -0.31783724519578205 (allowed: "
        "within 3.2e-08 of 0, as OpenFOAM reads it)");
}

} // namespace

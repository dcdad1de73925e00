// axialAngularSpring.fmu against the law library: outputs equal the law's
// (a tilted axis and a turned reference orientation), a zero axis is named
// at fmi2ExitInitializationMode.
#include <gtest/gtest.h>

#include "ConnectorInputs.hpp"
#include "axialAngularSpring/AxialAngularSpring.hpp"

namespace {

using namespace fmuTest;

TEST(AxialAngularSpringFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("axialAngularSpring");
    Instance in(fmu);
    std::map<std::string, double> parameters = genericParameters(fmu);
    auto p = genericallyAttached<connectors::AxialAngularSpringParameters>();
    p.axis_B = Vector3(0.3, -1, 0.2);
    p.R_BA0 = Eigen::AngleAxisd(0.4, Vector3(1, 2, -1).normalized())
                  .toRotationMatrix();
    p.stiffness = 250.0; // genericParameters'
    p.damping = 15.0;
    addVector(parameters, "B.axis", p.axis_B);
    addMatrix(parameters, "referenceOrientation", p.R_BA0);
    ASSERT_EQ(in.initialize(parameters), fmi2OK) << in.lastMessage();
    const connectors::AxialAngularSpring law(p);
    ASSERT_NO_FATAL_FAILURE(stepBothWays(
        fmu, in, [&](const BodyKinematics& A, const BodyKinematics& B) {
            expectOutputs(in, law.evaluate(A, B));
        }));
}

TEST(AxialAngularSpringFmu, ZeroAxisIsNamedAtExitInitializationMode)
{
    LoadedFmu fmu("axialAngularSpring");
    expectInitializationRefused(
        fmu, {{"B.axis[1]", 0.0}, {"B.axis[2]", 0.0}, {"B.axis[3]", 0.0}},
        "fmi2ExitInitializationMode: axialAngularSpring: parameter B.axis = "
        "(0, 0, 0) has no direction (allowed: a finite vector of length >= "
        "1e-12, normalised by the law)");
}

} // namespace

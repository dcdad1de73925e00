// coulombFriction.fmu against the law library: outputs (the interface's
// and slidingVelocity, friction) equal the law's values, with a guide and
// without; bad parameters are named at fmi2ExitInitializationMode.
#include <gtest/gtest.h>

#include "ConnectorInputs.hpp"
#include "coulombFriction/CoulombFriction.hpp"

namespace {

using namespace fmuTest;

std::map<std::string, double>
fmuParameters(const connectors::CoulombFrictionParameters& p)
{
    std::map<std::string, double> m
        = {{"frictionForce", p.frictionForce},
           {"regularisationVelocity", p.regularisationVelocity}};
    addVector(m, "A.p", p.p_AoP_A);
    addVector(m, "B.p", p.p_BoQ_B);
    addVector(m, "B.axis", p.axis_B);
    return m;
}

void expectOutputs(Instance& in, const connectors::CoulombFrictionResult& r)
{
    std::vector<std::string> names = connectorOutputs();
    names.insert(names.end(), {"slidingVelocity", "friction"});
    std::vector<double> values = flatten(r.loads);
    values.insert(values.end(), {r.slidingVelocity, r.friction});
    fmuTest::expectOutputs(in, names, values);
}

TEST(CoulombFrictionFmu, OutputsEqualTheLaw)
{
    // v_s of the order of the generic relative velocities (~1 m/s), so
    // that the force is neither saturated nor linear
    for (const Vector3& axis : {Vector3(0, 0, 0), Vector3(1, -2, 0.5)}) {
        auto p = genericallyAttached<connectors::CoulombFrictionParameters>();
        p.axis_B = axis;
        p.frictionForce = 0.45;
        p.regularisationVelocity = 0.3;
        LoadedFmu fmu("coulombFriction");
        Instance in(fmu);
        ASSERT_EQ(in.initialize(fmuParameters(p)), fmi2OK) << in.lastMessage();
        const connectors::CoulombFriction law(p);
        ASSERT_NO_FATAL_FAILURE(stepBothWays(
            fmu, in, [&](const BodyKinematics& A, const BodyKinematics& B) {
                expectOutputs(in, law.evaluateSliding(A, B));
            }));
    }
}

TEST(CoulombFrictionFmu, BadParametersAreNamedAtExitInitializationMode)
{
    LoadedFmu fmu("coulombFriction");
    expectInitializationRefused(
        fmu, {{"regularisationVelocity", 0.0}},
        "fmi2ExitInitializationMode: coulombFriction: parameter "
        "regularisationVelocity = 0 m/s is out of range (allowed: finite and "
        "> 0)");
    expectInitializationRefused(
        fmu, {{"frictionForce", -0.3}},
        "fmi2ExitInitializationMode: coulombFriction: parameter frictionForce "
        "= -0.3 N is out of range (allowed: finite and >= 0)");
    expectInitializationRefused(
        fmu, {{"B.axis[3]", 1e-13}},
        "fmi2ExitInitializationMode: coulombFriction: parameter B.axis = (0, "
        "0, 1e-13) has no direction (allowed: (0, 0, 0) for friction in every "
        "direction, or a finite vector of length >= 1e-12, normalised by the "
        "law)");
}

} // namespace

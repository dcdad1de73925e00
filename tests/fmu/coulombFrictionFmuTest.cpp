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
        connectors::CoulombFrictionParameters p;
        p.p_AoP_A = Vector3(0.1, -0.2, 0.3);
        p.p_BoQ_B = Vector3(-0.4, 0.05, 0.2);
        p.axis_B = axis;
        p.frictionForce = 0.45;
        p.regularisationVelocity = 0.3;
        LoadedFmu fmu("coulombFriction");
        Instance in(fmu);
        ASSERT_EQ(in.initialize(fmuParameters(p)), fmi2OK) << in.lastMessage();
        const connectors::CoulombFriction law(p);
        ASSERT_EQ(in.set(inputs(genericA(), genericB())), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.01, fmi2True), fmi2OK);
        expectOutputs(in, law.evaluateSliding(genericA(), genericB()));
        ASSERT_EQ(in.set(inputs(genericB(), genericA())), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, 0.01, 0.02, fmi2True), fmi2OK);
        expectOutputs(in, law.evaluateSliding(genericB(), genericA()));
    }
}

TEST(CoulombFrictionFmu, BadParametersAreNamedAtExitInitializationMode)
{
    LoadedFmu fmu("coulombFriction");
    {
        Instance in(fmu);
        EXPECT_EQ(in.initialize({{"regularisationVelocity", 0.0}}), fmi2Error);
        EXPECT_EQ(in.lastMessage(),
                  "fmi2ExitInitializationMode: coulombFriction: parameter "
                  "regularisationVelocity = 0 m/s is out of range (allowed: "
                  "finite and > 0)");
    }
    {
        Instance in(fmu);
        EXPECT_EQ(in.initialize({{"frictionForce", -0.3}}), fmi2Error);
        EXPECT_EQ(in.lastMessage(),
                  "fmi2ExitInitializationMode: coulombFriction: parameter "
                  "frictionForce = -0.3 N is out of range (allowed: finite "
                  "and >= 0)");
    }
    {
        Instance in(fmu);
        EXPECT_EQ(in.initialize({{"B.axis[3]", 1e-13}}), fmi2Error);
        EXPECT_EQ(in.lastMessage(),
                  "fmi2ExitInitializationMode: coulombFriction: parameter "
                  "B.axis = (0, 0, 1e-13) has no direction (allowed: (0, 0, "
                  "0) for friction in every direction, or a finite vector of "
                  "length >= 1e-12, normalised by the law)");
    }
}

} // namespace

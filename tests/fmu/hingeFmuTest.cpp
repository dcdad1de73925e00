// hinge.fmu through its C entry points: outputs equal the law, the angle
// state across steps (several turns, rollback with fmi2SetFMUstate,
// serialization into another instance), opposite axes, bad parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "ConnectorInputs.hpp"
#include "hinge/Hinge.hpp"

namespace {

using namespace fmuTest;

const std::vector<std::string> hingeOutputs
    = {"angle", "angleRate", "gap", "misalignment", "ptoTorque", "ptoPower"};

connectors::HingeParameters lawParameters()
{
    connectors::HingeParameters p;
    p.p_AoP_A = Vector3(0.1, -0.2, 0.3);
    p.p_BoQ_B = Vector3(-0.4, 0.05, 0.2);
    p.axis_A = Vector3(0, 1, 1);
    p.axis_B = Vector3(1, 0, 0);
    p.ref_A = Vector3(1, 0, 0);
    p.ref_B = Vector3::Zero();
    p.stiffness = 2e4;
    p.damping = 30.0;
    p.rotationalStiffness = 500.0;
    p.rotationalDamping = 2.0;
    p.ptoStiffness = 40.0;
    p.ptoDamping = 6.0;
    p.ptoRestAngle = -0.3;
    return p;
}

std::map<std::string, double>
fmuParameters(const connectors::HingeParameters& p)
{
    std::map<std::string, double> m
        = {{"stiffness", p.stiffness},
           {"damping", p.damping},
           {"rotationalStiffness", p.rotationalStiffness},
           {"rotationalDamping", p.rotationalDamping},
           {"ptoStiffness", p.ptoStiffness},
           {"ptoDamping", p.ptoDamping},
           {"ptoRestAngle", p.ptoRestAngle}};
    addVector(m, "A.p", p.p_AoP_A);
    addVector(m, "B.p", p.p_BoQ_B);
    addVector(m, "A.axis", p.axis_A);
    addVector(m, "B.axis", p.axis_B);
    addVector(m, "A.ref", p.ref_A);
    addVector(m, "B.ref", p.ref_B);
    return m;
}

std::vector<double> expected(const connectors::HingeResult& h)
{
    std::vector<double> values = flatten(h.loads);
    values.insert(
        values.end(),
        {h.angle, h.angleRate, h.gap, h.misalignment, h.ptoTorque, h.ptoPower});
    return values;
}

std::vector<std::string> allOutputs()
{
    std::vector<std::string> names = connectorOutputs();
    names.insert(names.end(), hingeOutputs.begin(), hingeOutputs.end());
    return names;
}

void expectOutputs(Instance& in, const connectors::HingeResult& h)
{
    fmuTest::expectOutputs(in, allOutputs(), expected(h));
}

//- A body turned by `angle` about the global axis (0, 1, 1) at the origin
//  and B fixed so that the relative angle follows `angle`
BodyKinematics turned(double angle)
{
    return kinematics(Vector3::Zero(), angle, Vector3(0, 1, 1), Vector3::Zero(),
                      Vector3(0, 0.5, 0.5));
}

TEST(HingeFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("hinge");
    Instance in(fmu);
    const connectors::HingeParameters p = lawParameters();
    ASSERT_EQ(in.initialize(fmuParameters(p)), fmi2OK) << in.lastMessage();
    const connectors::Hinge law(p);
    ASSERT_EQ(in.set(inputs(genericA(), genericB())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.01, fmi2True), fmi2OK)
        << in.lastMessage();
    const connectors::HingeResult first
        = law.evaluate(genericA(), genericB(), 0.0);
    expectOutputs(in, first);
    ASSERT_EQ(in.set(inputs(genericB(), genericA())), fmi2OK);
    expectOutputs(in, law.evaluate(genericB(), genericA(), first.angle));
}

TEST(HingeFmu, AngleStateFollowsTurnsRollbackAndRestart)
{
    // B (the world, at rest) keeps still while A turns about the hinge axis
    // (0,1,1)/sqrt 2 by 0.25 rad per step, three full turns: the relative
    // angle of B seen from A falls by 0.25 per step with no jump.
    LoadedFmu fmu("hinge");
    Instance in(fmu);
    std::map<std::string, double> parameters = fmuParameters(lawParameters());
    addVector(parameters, "A.p", Vector3::Zero());
    addVector(parameters, "B.p", Vector3::Zero());
    addVector(parameters, "B.axis", Vector3(0, 1, 1));
    ASSERT_EQ(in.initialize(parameters), fmi2OK) << in.lastMessage();
    const BodyKinematics world;
    const fmi2ValueReference angle = fmu.ref("angle");
    const int steps = int(3 * 2 * EIGEN_PI / 0.25) + 1;
    double t = 0.0, start = 0.0;
    fmi2FMUstate saved = nullptr;
    for (int i = 0; i <= steps; ++i) {
        ASSERT_EQ(in.set(inputs(turned(0.25 * i), world)), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, t, 0.1, fmi2True), fmi2OK)
            << in.lastMessage();
        t += 0.1;
        if (i == 0) {
            start = in.get("angle");
        }
        // Round-off of one rotation matrix per step, ~1e-15 rad each.
        ASSERT_NEAR(in.get("angle"), start - 0.25 * i, 1e-12) << "step " << i;
        EXPECT_NEAR(in.get("angleRate"), -0.5 * std::sqrt(2.0), 1e-15);
        if (i == steps / 2) {
            ASSERT_EQ(fmu.api.GetFMUstate(in.c, &saved), fmi2OK);
        }
    }
    const double end = in.get("angle");
    EXPECT_LT(end - start, -6 * EIGEN_PI); // three turns, not wrapped

    // Rollback: the angle returns with the state and the next step
    // continues from there (a repeated time step of PIMPLE).
    ASSERT_EQ(fmu.api.SetFMUstate(in.c, saved), fmi2OK);
    double value = 0.0;
    ASSERT_EQ(fmu.api.GetReal(in.c, &angle, 1, &value), fmi2OK);
    EXPECT_NEAR(value, start - 0.25 * (steps / 2), 1e-12);
    const double tSaved = 0.1 * (steps / 2 + 1);
    ASSERT_EQ(in.set(inputs(turned(0.25 * (steps / 2 + 1)), world)), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, tSaved, 0.1, fmi2True), fmi2OK)
        << in.lastMessage();
    EXPECT_NEAR(in.get("angle"), start - 0.25 * (steps / 2 + 1), 1e-12);

    // Restart: the serialized state carries the angle into a new instance.
    std::size_t size = 0;
    ASSERT_EQ(fmu.api.SerializedFMUstateSize(in.c, saved, &size), fmi2OK);
    std::vector<fmi2Byte> bytes(size);
    ASSERT_EQ(fmu.api.SerializeFMUstate(in.c, saved, bytes.data(), size),
              fmi2OK);
    Instance other(fmu);
    fmi2FMUstate restored = nullptr;
    ASSERT_EQ(
        fmu.api.DeSerializeFMUstate(other.c, bytes.data(), size, &restored),
        fmi2OK);
    ASSERT_EQ(fmu.api.SetFMUstate(other.c, restored), fmi2OK);
    ASSERT_EQ(other.set(inputs(turned(0.25 * (steps / 2 + 1)), world)), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(other.c, tSaved, 0.1, fmi2True), fmi2OK);
    EXPECT_NEAR(other.get("angle"), start - 0.25 * (steps / 2 + 1), 1e-12);
    EXPECT_EQ(fmu.api.FreeFMUstate(in.c, &saved), fmi2OK);

    // fmi2Reset starts the angle again in [-pi, pi].
    ASSERT_EQ(fmu.api.Reset(in.c), fmi2OK);
    ASSERT_EQ(in.initialize(parameters), fmi2OK);
    ASSERT_EQ(in.set(inputs(turned(0.25 * steps), world)), fmi2OK);
    EXPECT_LE(std::abs(in.get("angle")), EIGEN_PI);
}

TEST(HingeFmu, OppositeAxesGiveFiniteOutputs)
{
    LoadedFmu fmu("hinge");
    Instance in(fmu);
    ASSERT_EQ(in.initialize({{"rotationalStiffness", 10.0}}), fmi2OK);
    const BodyKinematics flipped
        = kinematics(Vector3::Zero(), EIGEN_PI, Vector3(1, 0, 0),
                     Vector3::Zero(), Vector3::Zero());
    ASSERT_EQ(in.set(inputs(BodyKinematics(), flipped)), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK)
        << in.lastMessage();
    // theta = pi to round-off; moment on B = 10 pi e_A, e_A = x (derived)
    EXPECT_NEAR(in.get("misalignment"), EIGEN_PI, 1e-15);
    EXPECT_NEAR(in.get("B.M[1]"), 10 * EIGEN_PI, 1e-13);
    EXPECT_NEAR(in.get("A.M[1]"), -10 * EIGEN_PI, 1e-13);
    std::vector<double> out;
    ASSERT_EQ(in.get(allOutputs(), out), fmi2OK);
    for (const double v : out) {
        EXPECT_TRUE(std::isfinite(v));
    }
}

TEST(HingeFmu, BadParametersAreNamedAtExitInitializationMode)
{
    LoadedFmu fmu("hinge");
    const std::vector<std::pair<std::map<std::string, double>, std::string>>
        cases = {
            {{{"rotationalStiffness", -1.0}},
             "parameter rotationalStiffness = -1 N.m/rad is out of range "
             "(allowed: finite and >= 0)"},
            {{{"A.axis[3]", 0.0}},
             "parameter A.axis = (0, 0, 0) has no direction (allowed: a finite "
             "vector of length >= 1e-12, normalised by the law)"},
            {{{"B.ref[3]", 4.0}},
             "parameter B.ref = (0, 0, 4) is parallel to B.axis (allowed: a "
             "direction off the axis, or (0, 0, 0) to derive one)"},
        };
    for (const auto& [parameters, message] : cases) {
        Instance in(fmu);
        EXPECT_EQ(in.initialize(parameters), fmi2Error);
        EXPECT_EQ(in.lastMessage(),
                  "fmi2ExitInitializationMode: hinge: " + message);
        EXPECT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2Error);
    }
}

} // namespace

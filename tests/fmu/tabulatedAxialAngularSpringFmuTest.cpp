// tabulatedAxialAngularSpring.fmu against the law library: outputs equal the
// law's (a tilted axis, a turned reference orientation, a table of 5 points
// in degrees repeated), in FMI 2.0 and 3.0; a table that is not strictly
// increasing, too short or too long, and a point beyond table.points, are
// named at fmi2ExitInitializationMode; outOfBounds error fails the step.
#include <gtest/gtest.h>

#include "ConnectorInputs.hpp"
#include "Fmi3Harness.hpp"
#include "tabulatedAxialAngularSpring/TabulatedAxialAngularSpring.hpp"

namespace {

using namespace fmuTest;
using connectors::OutOfBounds;
using Parameters = connectors::TabulatedAxialAngularSpringParameters;

const char* const name = "tabulatedAxialAngularSpring";

//- The FMU's parameters for p (the table in table.angle[k], table.moment[k])
std::map<std::string, double> fmuParameters(const LoadedFmu& fmu,
                                            const Parameters& p)
{
    std::map<std::string, double> parameters = genericParameters(fmu);
    addVector(parameters, "B.axis", p.axis_B);
    addMatrix(parameters, "referenceOrientation", p.R_BA0);
    parameters["table.points"] = double(p.angle.size());
    for (std::size_t k = 0; k < p.angle.size(); ++k) {
        const std::string index = "[" + std::to_string(k + 1) + "]";
        parameters["table.angle" + index] = p.angle[k];
        parameters["table.moment" + index] = p.moment[k];
    }
    parameters["angleInDegrees"] = p.angleInDegrees ? 1.0 : 0.0;
    parameters["outOfBounds"] = double(p.outOfBounds);
    parameters["damping"] = p.damping;
    return parameters;
}

//- A softening spring in degrees over -90 to 90, repeated beyond
Parameters softening()
{
    auto p = genericallyAttached<Parameters>();
    p.axis_B = Vector3(0.3, -1, 0.2);
    p.R_BA0 = Eigen::AngleAxisd(0.4, Vector3(1, 2, -1).normalized())
                  .toRotationMatrix();
    p.angle = {-90.0, -30.0, 0.0, 30.0, 90.0};
    p.moment = {80.0, 50.0, 0.0, -50.0, -80.0};
    p.angleInDegrees = true;
    p.outOfBounds = OutOfBounds::repeat;
    p.damping = 15.0; // genericParameters'
    return p;
}

TEST(TabulatedAxialAngularSpringFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu(name);
    Instance in(fmu);
    const Parameters p = softening();
    ASSERT_EQ(in.initialize(fmuParameters(fmu, p)), fmi2OK) << in.lastMessage();
    const connectors::TabulatedAxialAngularSpring law(p);
    ASSERT_NO_FATAL_FAILURE(stepBothWays(
        fmu, in, [&](const BodyKinematics& A, const BodyKinematics& B) {
            expectOutputs(in, law.evaluate(A, B));
        }));
}

TEST(TabulatedAxialAngularSpringFmu, Fmi3OutputsEqualTheLaw)
{
    LoadedFmu fmu(name);
    const LoadedFmu3 fmu3(name);
    Instance3 in(fmu3);
    const Parameters p = softening();
    ASSERT_EQ(in.initialize(arrayValues(fmuParameters(fmu, p), fmu3)), fmi3OK)
        << in.lastMessage();
    ASSERT_EQ(in.set(arrayValues(inputs(genericA(), genericB()), fmu3)),
              fmi3OK);
    ASSERT_EQ(in.doStep(0.0, 0.01), fmi3OK) << in.lastMessage();
    const connectors::ConnectorResult r
        = connectors::TabulatedAxialAngularSpring(p).evaluate(genericA(),
                                                              genericB());
    const std::vector<double> MA = in.get("A.M"), MB = in.get("B.M");
    ASSERT_EQ(MA.size(), 3u);
    ASSERT_EQ(MB.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        // Tolerance: as expectOutputs, the same law on the same doubles
        EXPECT_NEAR(MA[i], r.A.m_Ko_W[i], 1e-13 * (1 + std::abs(MA[i])));
        EXPECT_NEAR(MB[i], r.B.m_Ko_W[i], 1e-13 * (1 + std::abs(MB[i])));
    }
    EXPECT_NEAR(in.get("potentialEnergy").at(0), r.potentialEnergy,
                1e-13 * (1 + std::abs(r.potentialEnergy)));
    EXPECT_NEAR(in.get("dissipatedPower").at(0), r.dissipatedPower,
                1e-13 * (1 + r.dissipatedPower));
}

TEST(TabulatedAxialAngularSpringFmu, TableIsNamedAtExitInitializationMode)
{
    LoadedFmu fmu(name);
    const std::string prefix
        = "fmi2ExitInitializationMode: tabulatedAxialAngularSpring: ";
    expectInitializationRefused(
        fmu,
        {{"table.points", 3.0},
         {"table.angle[1]", -1.0},
         {"table.angle[2]", 1.0},
         {"table.angle[3]", 1.0}},
        prefix
            + "parameter table.angle[3] = 1 rad is out of range (allowed: > "
              "table.angle[2] = 1: the angles strictly increasing)");
    expectInitializationRefused(
        fmu, {{"table.points", 1.0}},
        prefix
            + "parameter table.points = 1 is out of range (allowed: an "
              "integer from 2 to 64)");
    expectInitializationRefused(
        fmu, {{"table.points", 65.0}},
        prefix
            + "parameter table.points = 65 is out of range (allowed: an "
              "integer from 2 to 64)");
    expectInitializationRefused(
        fmu, {{"table.moment[3]", 5.0}},
        prefix
            + "parameter table.moment[3] = 5 N.m is out of range (allowed: 0 "
              "beyond table.points = 2: the table is its first table.points "
              "points)");
    expectInitializationRefused(
        fmu, {{"outOfBounds", 4.0}},
        prefix
            + "parameter outOfBounds = 4 is out of range (allowed: 0 (error), "
              "1 (warn), 2 (clamp) or 3 (repeat))");
}

TEST(TabulatedAxialAngularSpringFmu, ErrorOutsideTheTableFailsTheStep)
{
    // The default table spans -1 to 1 rad; A turned 1.5 rad about B.axis
    LoadedFmu fmu(name);
    Instance in(fmu);
    ASSERT_EQ(in.initialize({{"outOfBounds", 0.0}}), fmi2OK)
        << in.lastMessage();
    BodyKinematics A = genericB();
    A.R_WK = genericB().R_WK
        * Eigen::AngleAxisd(1.5, Vector3::UnitZ()).toRotationMatrix();
    A.w_WK_W = genericB().w_WK_W;
    ASSERT_EQ(in.set(inputs(A, genericB())), fmi2OK);
    EXPECT_EQ(fmu.api.DoStep(in.c, 0.0, 0.01, fmi2True), fmi2Error);
    // The angle's last digits are acos's: the message from "rad" on
    EXPECT_NE(in.lastMessage().find("rad outside the table's [-1, 1) with "
                                    "outOfBounds error (0)"),
              std::string::npos)
        << in.lastMessage();
}

} // namespace

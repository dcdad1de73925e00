// mooringLine.fmu in moving water: the parameters of the free surface,
// current, seabed friction and end inertia reach the law; the flow inputs
// shape.Ux/Uy/Uz[k] (declared as the interface page says) reach it point
// by point from the fairlead, and equal to a uniform current they give the
// current's run; shape.tension[k] is the law's tension along the line.
#include <gtest/gtest.h>

#include <cmath>

#include "mooringLineFmuSupport.hpp"

namespace {

using namespace fmuTest;
using namespace mooringLineFmuTest;

//- The chain of the FMU tests (mooringLineFmuSupport.hpp) in water whose
//  surface (z = 41 m) the fairlead (40 +- 1 m) crosses, in a current,
//  with seabed friction, without the ends' inertia
const std::map<std::string, double> water
    = {{"freeSurface", 1.0},         {"waterLevel", 41.0},
       {"seabedFriction", 0.5},      {"frictionVelocity", 0.02},
       {"endInertia", 0.0},          {"current.surface[1]", 0.5},
       {"current.surface[2]", -0.2}, {"current.seabed[2]", 0.2}};

connectors::MooringLineParameters lawInWater()
{
    connectors::MooringLineParameters p = lawParameters();
    p.freeSurface = true;
    p.waterLevel = 41.0;
    p.seabedFriction = 0.5;
    p.frictionVelocity = 0.02;
    p.endInertia = false;
    p.currentSurface = Vector3(0.5, -0.2, 0.0);
    p.currentSeabed = Vector3(0.0, 0.2, 0.0);
    return p;
}

std::vector<std::string> names()
{
    std::vector<std::string> n
        = {"A.F[1]", "A.F[2]", "A.F[3]", "fairleadTension", "anchorTension"};
    for (int k = 1; k <= 11; ++k) {
        n.push_back("shape.tension[" + std::to_string(k) + "]");
    }
    return n;
}

TEST(MooringLineWaterFmu, ParametersAndFlowInputsReachTheLaw)
{
    // flow varying along the line, point 1 at the fairlead: a wrong order
    // or axis would give another run
    std::vector<Vector3> flow;
    for (int k = 0; k < 11; ++k) {
        flow.emplace_back(0.05 * k, -0.03 * k, 0.01);
    }
    LoadedFmu fmu("mooringLine");
    Instance in(fmu);
    ASSERT_EQ(initialise(fmu, in, water), fmi2OK) << in.lastMessage();
    connectors::MooringLine law(lawInWater());
    besideTheLaw(
        law, 30,
        [&](int k, double t, double h, connectors::MooringLineState& s) {
            ASSERT_EQ(in.set(inputs(floater(t + h), BodyKinematics())), fmi2OK);
            ASSERT_EQ(in.set(flowInputs(flow)), fmi2OK);
            ASSERT_EQ(fmu.api.DoStep(in.c, t, h, fmi2True), fmi2OK)
                << in.lastMessage();
            std::vector<double> got;
            ASSERT_EQ(in.get(names(), got), fmi2OK);
            law.advance(s, floater(t + h), BodyKinematics(), h, flow);
            const auto want
                = law.evaluate(s, floater(t + h), BodyKinematics(), 11, flow);
            // the same code in two binaries: 1e-5 of the tension
            expectFloaterForceNear(got, want, k);
            const double T = want.fairleadTension;
            for (int i = 0; i < 11; ++i) {
                EXPECT_NEAR(got[std::size_t(5 + i)],
                            want.shapeTension[std::size_t(i)], 1e-5 * T)
                    << k << " " << i;
            }
            // the ends of shape.tension are the end tensions (the same numbers)
            EXPECT_EQ(got[5], got[3]);
            EXPECT_EQ(got[15], got[4]);
        });
}

TEST(MooringLineWaterFmu, UniformFlowInputsEqualTheCurrent)
{
    // the same uniform water velocity as the current parameters or as the
    // flow inputs (zero current): the same run, to round-off (the flow is
    // interpolated between the points, (1 - f) U + f U)
    const Vector3 U(0.4, 0.3, 0.0);
    std::map<std::string, double> byCurrent = water;
    std::map<std::string, double> byFlow = water;
    for (int i = 1; i <= 3; ++i) {
        const std::string c = "[" + std::to_string(i) + "]";
        byCurrent["current.surface" + c] = byCurrent["current.seabed" + c]
            = U[i - 1];
        byFlow["current.surface" + c] = byFlow["current.seabed" + c] = 0.0;
    }
    LoadedFmu fmu("mooringLine");
    Instance a(fmu), b(fmu);
    ASSERT_EQ(initialise(fmu, a, byCurrent), fmi2OK) << a.lastMessage();
    ASSERT_EQ(initialise(fmu, b, byFlow), fmi2OK) << b.lastMessage();
    const double h = 0.1;
    double largest = 0.0;
    for (int k = 0; k < 30; ++k) {
        const double t = k * h;
        for (Instance* in : {&a, &b}) {
            ASSERT_EQ(in->set(inputs(floater(t + h), BodyKinematics())),
                      fmi2OK);
        }
        ASSERT_EQ(b.set(flowInputs(std::vector<Vector3>(11, U))), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(a.c, t, h, fmi2True), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(b.c, t, h, fmi2True), fmi2OK);
        std::vector<double> x, y;
        ASSERT_EQ(a.get(names(), x), fmi2OK);
        ASSERT_EQ(b.get(names(), y), fmi2OK);
        for (std::size_t i = 0; i < x.size(); ++i) {
            largest = std::max(largest, std::abs(x[i] - y[i]) / x[3]);
        }
    }
    // round-off of the velocities (1e-16) carried through 30 steps of a
    // line whose tension is 1e5 N: 1e-9 of it
    EXPECT_LT(largest, 1e-9);
}

TEST(MooringLineWaterFmu, FlowInputsAreDeclared)
{
    const LoadedFmu fmu("mooringLine");
    for (const char* axis : {"x", "y", "z"}) {
        for (int k = 1; k <= 11; ++k) {
            const std::string name
                = std::string("shape.U") + axis + "[" + std::to_string(k) + "]";
            const pugi::xml_node v
                = fmu.description.child("fmiModelDescription")
                      .child("ModelVariables")
                      .find_child_by_attribute("ScalarVariable", "name",
                                               name.c_str());
            ASSERT_TRUE(v) << name;
            EXPECT_STREQ(v.attribute("causality").value(), "input") << name;
            EXPECT_STREQ(v.attribute("variability").value(), "continuous")
                << name;
            EXPECT_STREQ(v.child("Real").attribute("unit").value(), "m/s")
                << name;
            EXPECT_STREQ(v.child("Real").attribute("start").value(), "0")
                << name;
        }
    }
}

TEST(MooringLineWaterFmu, ParameterErrorsAreNamed)
{
    LoadedFmu fmu("mooringLine");
    for (const auto& [name, value, message] :
         {std::tuple<std::string, double, std::string> {
              "freeSurface", 2.0,
              "mooringLine: parameter freeSurface = 2 is out of range "
              "(allowed: 0 or 1)"},
          {"endInertia", 0.5,
           "mooringLine: parameter endInertia = 0.5 is out of range "
           "(allowed: 0 or 1)"},
          {"seabedFriction", -1.0,
           "mooringLine: parameter seabedFriction = -1 is out of range "
           "(allowed: finite and >= 0)"},
          {"frictionVelocity", 0.0,
           "mooringLine: parameter frictionVelocity = 0 m/s is out of range "
           "(allowed: finite and > 0)"},
          {"current.seabed[3]", INFINITY,
           "mooringLine: parameter current.seabed[3] = inf m/s is out of "
           "range (allowed: finite)"},
          {"waterLevel", NAN,
           "mooringLine: parameter waterLevel = nan m is out of range "
           "(allowed: finite)"}}) {
        Instance in(fmu);
        std::map<std::string, double> p = chainParameters;
        p.insert(water.begin(), water.end());
        p[name] = value;
        EXPECT_EQ(in.initialize(p), fmi2Error) << name;
        EXPECT_EQ(in.lastMessage(), "fmi2ExitInitializationMode: " + message);
    }
}

} // namespace

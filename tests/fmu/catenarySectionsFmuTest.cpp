// catenary.fmu with sections and joint points (section<k>.*, joint<k>.*):
// outputs equal the law's for a chain, a rope and a clump weight; the
// parameters refused by name; two touchdowns refused at a step.
#include <gtest/gtest.h>

#include <cmath>

#include "ConnectorInputs.hpp"
#include "catenary/Catenary.hpp"

namespace {

using namespace fmuTest;

//- 60 m of chain from the anchor, a 20 kN clump weight, 60 m of rope
const std::map<std::string, double> chainClumpRope
    = {{"unstretchedLength", 60.0},
       {"EA", 5e8},
       {"weight", 700.0},
       {"seabedContact", 1.0},
       {"seabedFriction", 0.3},
       {"joint1.weight", 2e4},
       {"section2.unstretchedLength", 60.0},
       {"section2.EA", 5e7},
       {"section2.weight", 50.0}};

connectors::CatenaryParameters lawParameters()
{
    connectors::CatenaryParameters p;
    p.line.length = 60.0;
    p.line.EA = 5e8;
    p.line.weight = 700.0;
    p.line.seabedContact = true;
    p.line.seabedFriction = 0.3;
    connectors::CatenarySection rope;
    rope.jointWeight = 2e4;
    rope.length = 60.0;
    rope.EA = 5e7;
    rope.weight = 50.0;
    p.line.sections = {rope};
    return p;
}

//- The fairlead swept from a slack line with the clump on the seabed to
//  one that lifts it
BodyKinematics fairlead(double t)
{
    return kinematics(Vector3(100.0 + 4.0 * t, 0.0, 40.0), 0.0,
                      Vector3(0, 1, 0), Vector3(4.0, 0, 0), Vector3::Zero());
}

TEST(CatenarySectionsFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("catenary");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(chainClumpRope), fmi2OK) << in.lastMessage();
    const connectors::Catenary law(lawParameters());
    const std::vector<std::string> names
        = {"A.F[1]",         "A.F[3]",         "B.F[1]", "fairleadTension",
           "anchorTension",  "groundedLength", "H",      "V",
           "potentialEnergy"};
    double t = 0.0;
    for (int step = 0; step < 20; ++step, t += 0.1) {
        ASSERT_EQ(in.set(inputs(fairlead(t + 0.1), BodyKinematics())), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, t, 0.1, fmi2True), fmi2OK)
            << in.lastMessage();
        const connectors::CatenaryOutput c
            = law.evaluate(fairlead(t + 0.1), BodyKinematics(), nullptr, 0);
        std::vector<double> got;
        ASSERT_EQ(in.get(names, got), fmi2OK);
        // warm started against cold: both within Newton's 1e-10 L of the
        // spans, 1e-7 of the tension (catenaryFmuTest); 1e-6 asserted
        const double T = c.fairleadTension;
        const std::vector<double> want
            = {c.loads.A.f_W[0],       c.loads.A.f_W[2],
               c.loads.B.f_W[0],       T,
               c.anchorTension,        c.solution.groundedLength,
               c.solution.H,           c.solution.V,
               c.loads.potentialEnergy};
        for (std::size_t i = 0; i + 1 < want.size(); ++i) {
            EXPECT_NEAR(got[i], want[i], 1e-6 * T) << names[i] << " " << t;
        }
        EXPECT_NEAR(got.back(), want.back(), 1e-6 * std::abs(want.back()));
    }
}

TEST(CatenarySectionsFmu, ParametersAreRefusedByName)
{
    LoadedFmu fmu("catenary");
    const auto refused = [&](const std::map<std::string, double>& changes,
                             const std::string& message) {
        Instance in(fmu);
        std::map<std::string, double> p = chainClumpRope;
        for (const auto& c : changes) {
            p[c.first] = c.second;
        }
        EXPECT_EQ(in.initialize(p), fmi2Error);
        EXPECT_EQ(in.lastMessage(),
                  "fmi2ExitInitializationMode: catenary: parameter " + message);
    };
    refused({{"section2.unstretchedLength", -1.0}},
            "section2.unstretchedLength = -1 m is out of range (allowed: "
            "finite and >= 0; 0: no section 2)");
    refused({{"section2.unstretchedLength", 0.0},
             {"joint1.weight", 0.0},
             {"section3.unstretchedLength", 10.0}},
            "section3.unstretchedLength = 10 m is out of range (allowed: 0 "
            "while an earlier section's unstretchedLength is 0: the "
            "sections follow each other from B.p, without gaps)");
    refused({{"joint2.weight", 5.0}},
            "joint2.weight = 5 N is out of range (allowed: 0 without section "
            "3: a joint lies between two sections)");
    refused({{"section2.EA", 0.0}},
            "section2.EA = 0 N is out of range (allowed: finite and > 0)");
}

TEST(CatenarySectionsFmu, TwoTouchdownsAreAnErrorAtTheStep)
{
    // a buoy on the grounded chain: fmi2Error naming it, outputs finite
    LoadedFmu fmu("catenary");
    Instance in(fmu);
    std::map<std::string, double> p = chainClumpRope;
    p["joint1.weight"] = -3.5e4;
    ASSERT_EQ(in.initialize(p), fmi2OK) << in.lastMessage();
    ASSERT_EQ(in.set(inputs(fairlead(-7.5), BodyKinematics())), fmi2OK);
    EXPECT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2Error);
    EXPECT_NE(in.lastMessage().find(
                  "the buoy at joint 1 (between sections 1 and 2) (net "
                  "weight -35000 N, allowed >= 0 on the seabed)"),
              std::string::npos)
        << in.lastMessage();
}

} // namespace

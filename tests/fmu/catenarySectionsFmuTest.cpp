// catenary.fmu with sections and joint points (section<k>.*, joint<k>.*):
// outputs equal the law's for a chain, a rope and a clump weight, and so do
// the local variables of the sections' end tensions, the joints' positions
// and the shape points' sections; the parameters refused by name; two
// touchdowns refused at a step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

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
       {"section2.weight", 50.0},
       {"B.p[1]", 0.0}}; // the anchor at B's reference point

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

//- Steps the instance through the sweep, 20 steps of 0.1 s, and calls
//  check(t, the law's output at t) after each
template <class Check>
void sweep(LoadedFmu& fmu, Instance& in, const Check& check)
{
    const connectors::Catenary law(lawParameters());
    for (int step = 0; step < 20; ++step) {
        const double t = 0.1 * step;
        ASSERT_EQ(in.set(inputs(fairlead(t + 0.1), BodyKinematics())), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, t, 0.1, fmi2True), fmi2OK)
            << in.lastMessage();
        check(t + 0.1,
              law.evaluate(fairlead(t + 0.1), BodyKinematics(), nullptr, 0));
    }
}

TEST(CatenarySectionsFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("catenary");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(chainClumpRope), fmi2OK) << in.lastMessage();
    const std::vector<std::string> names
        = {"A.F[1]",         "A.F[3]",         "B.F[1]", "fairleadTension",
           "anchorTension",  "groundedLength", "H",      "V",
           "potentialEnergy"};
    sweep(fmu, in, [&](double t, const connectors::CatenaryOutput& c) {
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
    });
}

//- section.lowerTension[1..4], section.upperTension[1..4], joint.x[1..3],
//  joint.y, joint.z, shape.section[1..11]
std::vector<std::string> sectionLocals()
{
    std::vector<std::string> names;
    for (const std::string end : {"lower", "upper"}) {
        for (int k = 1; k <= 4; ++k) {
            names.push_back("section." + end + "Tension[" + std::to_string(k)
                            + "]");
        }
    }
    for (const std::string axis : {"x", "y", "z"}) {
        for (int k = 1; k <= 3; ++k) {
            names.push_back("joint." + axis + "[" + std::to_string(k) + "]");
        }
    }
    for (int k = 1; k <= 11; ++k) {
        names.push_back("shape.section[" + std::to_string(k) + "]");
    }
    return names;
}

TEST(CatenarySectionsFmu, SectionEndsJointsAndShapeSectionsEqualTheLaw)
{
    LoadedFmu fmu("catenary");
    // local variables: the outputs stay those of the uniform line
    const std::vector<std::string> locals = sectionLocals();
    std::size_t found = 0;
    for (const fmuImport::Variable& v : fmu.modelDescription().variables) {
        if (std::find(locals.begin(), locals.end(), v.name) != locals.end()) {
            EXPECT_EQ(v.causality, fmuImport::Causality::local) << v.name;
            ++found;
        }
    }
    EXPECT_EQ(found, locals.size());
    Instance in(fmu);
    ASSERT_EQ(in.initialize(chainClumpRope), fmi2OK) << in.lastMessage();
    // the shape points at 12 m steps of arc from the fairlead: 1 to 6 (the
    // joint, 60 m from the anchor) in section 2, 7 to 11 in section 1
    const std::vector<double> sections = {2, 2, 2, 2, 2, 2, 1, 1, 1, 1, 1};
    sweep(fmu, in, [&](double t, const connectors::CatenaryOutput& c) {
        std::vector<double> got;
        ASSERT_EQ(in.get(sectionLocals(), got), fmi2OK);
        ASSERT_EQ(c.sectionLowerTension.size(), 2u);
        ASSERT_EQ(c.joints.size(), 1u);
        const std::vector<double> tensions
            = {c.sectionLowerTension[0], c.sectionLowerTension[1], 0, 0,
               c.sectionUpperTension[0], c.sectionUpperTension[1], 0, 0};
        // warm started against cold (OutputsEqualTheLaw): 1e-6 of the
        // tension; the joint within 1e-6 of the line's length
        const double T = c.fairleadTension;
        for (std::size_t i = 0; i < tensions.size(); ++i) {
            EXPECT_NEAR(got[i], tensions[i], 1e-6 * T) << i << " " << t;
        }
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const std::size_t i = tensions.size() + 3 * axis;
            EXPECT_NEAR(got[i], c.joints[0][int(axis)], 1e-6 * 120.0)
                << axis << " " << t;
            EXPECT_EQ(got[i + 1], 0.0);
            EXPECT_EQ(got[i + 2], 0.0);
        }
        const std::vector<double> shape(got.end() - 11, got.end());
        EXPECT_EQ(shape, sections) << t;
    });
    // calculated by the FMU: not to be set
    EXPECT_EQ(in.set({{"section.lowerTension[1]", 1.0}}), fmi2Error);
    EXPECT_NE(in.lastMessage().find("section.lowerTension[1] (value "
                                    "reference"),
              std::string::npos)
        << in.lastMessage();
    EXPECT_NE(in.lastMessage().find(") is calculated by the FMU and cannot "
                                    "be set"),
              std::string::npos)
        << in.lastMessage();
}

TEST(CatenarySectionsFmu, AUniformLineIsItsOwnFirstSection)
{
    // no sections: section 1 from the anchor to the fairlead, every shape
    // point in it, the rest 0
    LoadedFmu fmu("catenary");
    Instance in(fmu);
    std::map<std::string, double> p = chainClumpRope;
    p["joint1.weight"] = 0.0;
    p["section2.unstretchedLength"] = 0.0;
    ASSERT_EQ(in.initialize(p), fmi2OK) << in.lastMessage();
    ASSERT_EQ(in.set(inputs(fairlead(0.0), BodyKinematics())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK)
        << in.lastMessage();
    std::vector<double> got;
    ASSERT_EQ(in.get(sectionLocals(), got), fmi2OK);
    std::vector<double> want(got.size(), 0.0);
    want[0] = in.get("anchorTension");
    want[4] = in.get("fairleadTension");
    std::fill(want.end() - 11, want.end(), 1.0);
    EXPECT_GT(want[4], want[0]);
    EXPECT_EQ(got, want);
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

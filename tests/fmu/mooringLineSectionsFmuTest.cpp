// mooringLine.fmu with sections: a chain, a rope and a clump weight between
// them give the law's outputs (section end tensions, the joint's
// position) and the section of each shape point (local variables
// shape.section); sections and joints it cannot use are refused with
// fmi2Error and a message naming the parameter and the allowed range.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "LawTestSupport.hpp"
#include "mooringLineFmuSupport.hpp"

namespace {

using namespace fmuTest;
using namespace mooringLineFmuTest;

//- A 40 m rope above the chain of the fixture (60 m) with a clump weight
//  of 2000 kg between them, under a water level of 50 m
const std::map<std::string, double> ropeAndClump
    = {{"unstretchedLength", 60.0},
       {"section2.unstretchedLength", 40.0},
       {"section2.EA", 5e6},
       {"section2.axialDamping", 2e4},
       {"section2.massPerLength", 10.0},
       {"section2.diameter", 0.08},
       {"section2.normalDrag", 1.0},
       {"section2.tangentialDrag", 0.02},
       {"section2.normalAddedMass", 1.0},
       {"section2.segments", 8.0},
       {"joint1.mass", 2000.0},
       {"joint1.volume", 0.25},
       {"joint1.dragArea", 0.5},
       {"joint1.addedMass", 1.0},
       {"waterLevel", 50.0}};

connectors::MooringLineParameters ropeAndClumpLaw()
{
    connectors::MooringLineParameters p = lawParameters();
    p.length = 60.0;
    p.waterLevel = 50.0;
    // d, w, EA, axial damping, Cn, Ct, Can, Cat; the clump's m, V, CdA, Ca
    p.sections = {connectors::references::sectionOf(
        {0.08, 10.0, 5e6, 2e4, 1.0, 0.02, 1.0, 0.0}, 40.0, 8,
        {2000.0, 0.25, 0.5, 1.0})};
    return p;
}

TEST(MooringLineSectionsFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("mooringLine");
    Instance in(fmu);
    ASSERT_EQ(initialise(fmu, in, ropeAndClump), fmi2OK) << in.lastMessage();
    connectors::MooringLine law(ropeAndClumpLaw());
    connectors::MooringLineState s = startState(law);
    const std::vector<std::string> names = {"fairleadTension",
                                            "anchorTension",
                                            "section.lowerTension[1]",
                                            "section.upperTension[1]",
                                            "section.lowerTension[2]",
                                            "section.upperTension[2]",
                                            "section.lowerTension[3]",
                                            "section.upperTension[4]",
                                            "joint.x[1]",
                                            "joint.y[1]",
                                            "joint.z[1]",
                                            "joint.z[2]",
                                            "joint.x[3]"};
    const double h = 0.1;
    for (int k = 0; k < 20; ++k) {
        const double t = k * h;
        ASSERT_EQ(in.set(inputs(floater(t + h), BodyKinematics())), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, t, h, fmi2True), fmi2OK)
            << in.lastMessage();
        std::vector<double> got;
        ASSERT_EQ(in.get(names, got), fmi2OK);
        law.advance(s, floater(t + h), BodyKinematics(), h);
        const auto want = law.evaluate(s, floater(t + h), BodyKinematics(), 0);
        // as MooringLineFmu.OutputsEqualTheLaw: two binaries, 1e-5
        const double T = want.fairleadTension;
        const std::vector<double> expected = {T,
                                              want.anchorTension,
                                              want.sectionLowerTension[0],
                                              want.sectionUpperTension[0],
                                              want.sectionLowerTension[1],
                                              want.sectionUpperTension[1],
                                              0.0,
                                              0.0,
                                              want.joints[0][0],
                                              want.joints[0][1],
                                              want.joints[0][2],
                                              0.0,
                                              0.0};
        for (std::size_t i = 0; i < names.size(); ++i) {
            EXPECT_NEAR(got[i], expected[i], i < 8 ? 1e-5 * T : 1e-6)
                << names[i] << " at step " << k;
        }
    }
}

TEST(MooringLineSectionsFmu, ShapePointsNameTheirSection)
{
    // 100 m of line, the shape points 10 m of arc apart from the fairlead:
    // 1 to 5 in the rope (5 at the joint, 60 m from the anchor: the
    // section towards A.p), 6 to 11 in the chain
    LoadedFmu fmu("mooringLine");
    std::vector<std::string> names;
    for (int k = 1; k <= 11; ++k) {
        names.push_back("shape.section[" + std::to_string(k) + "]");
    }
    for (const fmuImport::Variable& v : fmu.modelDescription().variables) {
        if (v.name.rfind("shape.section[", 0) == 0) {
            EXPECT_EQ(v.causality, fmuImport::Causality::local) << v.name;
        }
    }
    const std::vector<double> sections = {2, 2, 2, 2, 2, 1, 1, 1, 1, 1, 1};
    Instance in(fmu);
    ASSERT_EQ(initialise(fmu, in, ropeAndClump), fmi2OK) << in.lastMessage();
    std::vector<double> got;
    ASSERT_EQ(in.get(names, got), fmi2OK);
    EXPECT_EQ(got, sections);
    ASSERT_EQ(in.set(inputs(floater(0.1), BodyKinematics())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK)
        << in.lastMessage();
    ASSERT_EQ(in.get(names, got), fmi2OK);
    EXPECT_EQ(got, sections);
    // point 5 is the joint's node
    for (const char* axis : {"x", "y", "z"}) {
        EXPECT_NEAR(in.get(std::string("shape.") + axis + "[5]"),
                    in.get(std::string("joint.") + axis + "[1]"), 1e-12)
            << axis;
    }
    // a uniform line: every point in section 1
    Instance uniform(fmu);
    ASSERT_EQ(initialise(fmu, uniform, {}), fmi2OK) << uniform.lastMessage();
    ASSERT_EQ(uniform.get(names, got), fmi2OK);
    EXPECT_EQ(got, std::vector<double>(11, 1.0));
}

TEST(MooringLineSectionsFmu, SerializedStateContinuesInAnotherInstance)
{
    // the state holds the nodes of all sections (N = 10 + 8): a restart
    // (a new instance, no parameters set) continues bit for bit
    LoadedFmu fmu("mooringLine");
    Instance in(fmu);
    ASSERT_EQ(initialise(fmu, in, ropeAndClump), fmi2OK) << in.lastMessage();
    const std::vector<std::string> names
        = {"fairleadTension", "section.upperTension[1]", "joint.z[1]"};
    const auto step = [&](Instance& i, double t, double h) {
        EXPECT_EQ(i.set(inputs(floater(t + h), BodyKinematics())), fmi2OK);
        EXPECT_EQ(fmu.api.DoStep(i.c, t, h, fmi2True), fmi2OK);
        std::vector<double> out;
        EXPECT_EQ(i.get(names, out), fmi2OK);
        return out;
    };
    const double h = 0.1;
    for (int k = 0; k < 5; ++k) {
        step(in, k * h, h);
    }
    fmi2FMUstate saved = nullptr;
    ASSERT_EQ(fmu.api.GetFMUstate(in.c, &saved), fmi2OK);
    Instance other(fmu);
    ASSERT_EQ(other.restore(in.serialize(saved)), fmi2OK)
        << other.lastMessage();
    for (int k = 5; k < 10; ++k) {
        EXPECT_EQ(step(other, k * h, h), step(in, k * h, h)) << k;
    }
    EXPECT_EQ(fmu.api.FreeFMUstate(in.c, &saved), fmi2OK);
}

TEST(MooringLineSectionsFmu, UnusableSectionsAreRefusedByName)
{
    LoadedFmu fmu("mooringLine");
    struct Case {
        std::map<std::string, double> extra;
        std::string message;
    };
    const Case cases[] = {
        {{{"section3.unstretchedLength", 20.0}},
         "mooringLine: parameter section3.unstretchedLength = 20 m is out of "
         "range (allowed: 0 while an earlier section's unstretchedLength is "
         "0: the sections follow each other from B.p, without gaps)"},
        {{{"joint1.volume", 2.0}},
         "mooringLine: parameter joint1.volume = 2 m3 is out of range "
         "(allowed: 0 without section 2: a joint lies between two "
         "sections)"},
        {{{"section2.unstretchedLength", -5.0}},
         "mooringLine: parameter section2.unstretchedLength = -5 m is out of "
         "range (allowed: finite and >= 0; 0: no section 2)"},
        {{{"section2.unstretchedLength", 30.0}, {"joint1.mass", -1.0}},
         "mooringLine: parameter joint1.mass = -1 kg is out of range "
         "(allowed: finite and >= 0)"},
        {{{"section2.unstretchedLength", 30.0}, {"section2.segments", 2.5}},
         "mooringLine: parameter section2.segments = 2.5 is out of range "
         "(allowed: an integer from 1 to 1000)"},
        {{{"section2.unstretchedLength", 30.0}, {"section2.segments", 995.0}},
         "mooringLine: parameter section2.segments = 995 is out of range "
         "(allowed: an integer from 1 to 990: the sections' segments add up "
         "to at most 1000)"},
        {{{"section2.unstretchedLength", 30.0}, {"section2.diameter", 0.0}},
         "mooringLine: parameter section2.diameter = 0 m is out of range "
         "(allowed: > 0 with seabedContact = 1: the seabed carries the line "
         "over its contact area, diameter times length)"}};
    for (const Case& c : cases) {
        const std::map<std::string, double>& extra = c.extra;
        const std::string& message = c.message;
        Instance in(fmu);
        std::map<std::string, double> p = chainParameters;
        p.insert(extra.begin(), extra.end());
        EXPECT_EQ(in.initialize(p), fmi2Error);
        EXPECT_EQ(in.lastMessage(), "fmi2ExitInitializationMode: " + message);
    }
}

TEST(MooringLineSectionsFmu, BuoyAboveTheSurfaceIsRefused)
{
    // A buoy of 30 m3 between 60 m of chain and 40 m of rope lifts the
    // joint above the water level (0: the floater is at 42 m, in the air
    // for this test's purpose): refused at the start, naming the joint's
    // entries (not as "parameter ...": it depends on the inputs)
    LoadedFmu fmu("mooringLine");
    std::map<std::string, double> p = ropeAndClump;
    p["joint1.mass"] = 1000.0;
    p["joint1.volume"] = 30.0;
    p["waterLevel"] = 20.0;
    Instance in(fmu);
    EXPECT_EQ(initialise(fmu, in, p), fmi2Error);
    const std::string m = in.lastMessage();
    lawTest::expectStartsWithAndContains(
        m,
        "fmi2ExitInitializationMode: mooringLine: the buoy at joint1 "
        "(joint1.volume = 30 m3, joint1.mass = 1000 kg: a net lift of "
        "291847.5 N) holds the line above the water surface",
        "above waterLevel = 20 m (allowed: a joint at or below waterLevel");
    EXPECT_EQ(m.find("parameter"), std::string::npos) << m;
    // with the free surface the buoy floats at it: within the joint's
    // ramp of half a segment of either section, (6 + 5)/2 m, around it
    // (measured: 22.2 m, its buoyancy 10 % submerged)
    p["freeSurface"] = 1.0;
    Instance floating(fmu);
    ASSERT_EQ(initialise(fmu, floating, p), fmi2OK) << floating.lastMessage();
    EXPECT_NEAR(floating.get("joint.z[1]"), 20.0, 0.5 * 5.5);
}

} // namespace

// catenary.fmu through its C entry points: outputs equal the law, repeated
// steps after a state restore, parameter and geometry errors, and which
// FMU binaries depend on SUNDIALS.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "ConnectorInputs.hpp"
#include "catenary/Catenary.hpp"

namespace {

using namespace fmuTest;

const std::map<std::string, double> mooringParameters
    = {{"unstretchedLength", 100.0},
       {"EA", 5e7},
       {"weight", 700.0},
       {"seabedContact", 1.0},
       {"seabedFriction", 0.5},
       {"A.p[1]", 2.0},
       {"A.p[2]", -1.0},
       {"A.p[3]", -3.0},
       {"B.p[1]", 0.5},
       {"B.p[2]", 0.2},
       {"B.p[3]", -60.0}};

connectors::CatenaryParameters lawParameters()
{
    connectors::CatenaryParameters p;
    p.p_AoP_A = Vector3(2.0, -1.0, -3.0);
    p.p_BoQ_B = Vector3(0.5, 0.2, -60.0);
    p.line.length = 100.0;
    p.line.EA = 5e7;
    p.line.weight = 700.0;
    p.line.seabedContact = true;
    p.line.seabedFriction = 0.5;
    return p;
}

//- A floating body 70 m from the anchor in 58 m of water, pitched and moving
BodyKinematics floater(double t)
{
    return kinematics(Vector3(70.0 + 2.0 * std::sin(t), 3.0, 1.0 * std::cos(t)),
                      0.05, Vector3(0, 1, 0),
                      Vector3(2.0 * std::cos(t), 0, -std::sin(t)),
                      Vector3(0, 0.02, 0));
}

std::vector<std::string> lineOutputs()
{
    std::vector<std::string> names = connectorOutputs();
    for (const char* n :
         {"fairleadTension", "anchorTension", "groundedLength", "H", "V"}) {
        names.push_back(n);
    }
    for (const char* axis : {"x", "y", "z"}) {
        for (int i = 1; i <= 11; ++i) {
            names.push_back(std::string("shape.") + axis + "["
                            + std::to_string(i) + "]");
        }
    }
    for (int i = 1; i <= 11; ++i) {
        names.push_back("shape.tension[" + std::to_string(i) + "]");
    }
    return names;
}

TEST(CatenaryFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("catenary");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(mooringParameters), fmi2OK) << in.lastMessage();
    const connectors::Catenary law(lawParameters());
    double t = 0.0;
    for (int step = 0; step < 20; ++step, t += 0.1) {
        ASSERT_EQ(in.set(inputs(floater(t + 0.1), BodyKinematics())), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, t, 0.1, fmi2True), fmi2OK)
            << in.lastMessage();
        const connectors::CatenaryOutput c
            = law.evaluate(floater(t + 0.1), BodyKinematics(), nullptr, 11);
        std::vector<double> got;
        ASSERT_EQ(in.get(lineOutputs(), got), fmi2OK);
        std::vector<double> want
            = {c.loads.A.f_W[0], c.loads.A.f_W[1], c.loads.A.f_W[2]};
        // The FMU is warm started, the law here cold: both stop at a span
        // residual below 1e-10 L = 1e-8 m; with dT/dx ~ 1e5 N/m that is
        // 1e-3 N on tensions of ~1e5 N: 1e-7 relative, 1e-6 asserted.
        const double T = c.fairleadTension;
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(got[std::size_t(i)], c.loads.A.f_W[i], 1e-6 * T);
            EXPECT_NEAR(got[std::size_t(6 + i)], c.loads.B.f_W[i], 1e-6 * T);
        }
        EXPECT_NEAR(got[14], T, 1e-6 * T); // tension
        EXPECT_NEAR(got[17], T, 1e-6 * T); // fairleadTension
        EXPECT_NEAR(got[18], c.anchorTension, 1e-6 * T); // anchorTension
        EXPECT_NEAR(got[19], c.solution.groundedLength, 1e-6); // m
        EXPECT_NEAR(got[20], c.solution.H, 1e-6 * T);
        EXPECT_NEAR(got[21], c.solution.V, 1e-6 * T);
        for (int i = 0; i < 11; ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_NEAR(got[std::size_t(22 + 11 * axis + i)],
                            c.shape[std::size_t(i)][axis], 1e-6);
            }
            // the tension along the line (same warm/cold difference)
            EXPECT_NEAR(got[std::size_t(55 + i)],
                        c.shapeTension[std::size_t(i)], 1e-6 * T);
        }
        // its ends are the end tensions (same code, warm/cold difference)
        EXPECT_NEAR(got[55], got[17], 1e-6 * T);
        EXPECT_NEAR(got[65], got[18], 1e-6 * T);
        EXPECT_GT(got[19], 0.0); // part of the line lies on the seabed
    }
}

TEST(CatenaryFmu, RepeatedStepAfterRestoreIsIdentical)
{
    LoadedFmu fmu("catenary");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(mooringParameters), fmi2OK);
    fmi2FMUstate saved = nullptr;
    double t = 0.0;
    for (int step = 0; step < 50; ++step, t += 0.05) {
        ASSERT_EQ(fmu.api.GetFMUstate(in.c, &saved), fmi2OK);
        std::vector<double> first, second;
        ASSERT_EQ(in.set(inputs(floater(t + 0.05), BodyKinematics())), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, t, 0.05, fmi2True), fmi2OK);
        ASSERT_EQ(in.get(lineOutputs(), first), fmi2OK);
        ASSERT_EQ(fmu.api.SetFMUstate(in.c, saved), fmi2OK);
        ASSERT_EQ(in.set(inputs(floater(t + 0.05), BodyKinematics())), fmi2OK);
        ASSERT_EQ(fmu.api.DoStep(in.c, t, 0.05, fmi2True), fmi2OK);
        ASSERT_EQ(in.get(lineOutputs(), second), fmi2OK);
        EXPECT_EQ(first, second) << "step " << step; // bit for bit
    }
    EXPECT_EQ(fmu.api.FreeFMUstate(in.c, &saved), fmi2OK);
}

TEST(CatenaryFmu, ErrorsAreNamed)
{
    LoadedFmu fmu("catenary");
    expectInitializationRefused(
        fmu, changed(mooringParameters, {{"seabedContact", 0.5}}),
        "fmi2ExitInitializationMode: catenary: parameter seabedContact = "
        "0.5 is out of range (allowed: 0 or 1)");
    expectInitializationRefused(
        fmu, changed(mooringParameters, {{"EA", -1.0}}),
        "fmi2ExitInitializationMode: catenary: parameter EA = -1 N is out "
        "of range (allowed: finite and > 0)");
    Instance in(fmu);
    ASSERT_EQ(in.initialize(mooringParameters), fmi2OK);
    BodyKinematics sunk = floater(0.0);
    sunk.p_WKo_W[2] = -70.0;
    ASSERT_EQ(in.set(inputs(sunk, BodyKinematics())), fmi2OK);
    EXPECT_EQ(fmu.api.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2Error);
    EXPECT_EQ(
        in.lastMessage().rfind("fmi2DoStep: catenary: the fairlead is ", 0), 0u)
        << in.lastMessage();
    std::vector<double> out(lineOutputs().size(), 0.0);
    EXPECT_EQ(in.get(lineOutputs(), out), fmi2Error);
    for (const double v : out) {
        EXPECT_TRUE(std::isfinite(v));
    }
}

TEST(CatenaryFmu, SpringAndCatenaryCarryNoSundials)
{
    // Springs, dampers and the quasi-static catenary carry no SUNDIALS:
    // neither as a library they need nor linked in (the FMU binaries keep
    // their local symbols)
    for (const char* name : {"linearSpring", "catenary"}) {
        const LoadedFmu fmu(name);
        const std::string deps = onBinary("ldd", fmu);
        ASSERT_NE(deps.find("libc.so"), std::string::npos) << deps; // ldd ran
        EXPECT_EQ(deps.find("libsundials"), std::string::npos) << name << ":\n"
                                                               << deps;
        const std::string symbols = onBinary("nm", fmu);
        ASSERT_NE(symbols.find("fmi2DoStep"), std::string::npos)
            << name; // nm ran
        EXPECT_EQ(symbols.find("CVode"), std::string::npos)
            << name << " links CVODE in";
    }
}

} // namespace

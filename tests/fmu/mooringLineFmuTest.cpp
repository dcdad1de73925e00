// mooringLine.fmu through its C entry points: outputs equal the law, steps
// repeated after fmi2SetFMUstate (PIMPLE outer correctors) equal the
// uninterrupted run, serialized states continue identically in another
// instance, parameter errors (a seabed without diameter or stiffness, a
// line far shorter than its ends), and the SUNDIALS linked into the
// binary.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "LawTestSupport.hpp"
#include "mooringLineFmuSupport.hpp"

namespace {

using namespace fmuTest;
using namespace mooringLineFmuTest;

std::vector<std::string> names()
{
    std::vector<std::string> n = connectorOutputs();
    for (const char* extra :
         {"fairleadTension", "anchorTension", "groundedLength", "H", "V"}) {
        n.push_back(extra);
    }
    return n;
}

std::vector<double> step(const LoadedFmu& fmu, Instance& in, double t, double h)
{
    EXPECT_EQ(in.set(inputs(floater(t + h), BodyKinematics())), fmi2OK);
    EXPECT_EQ(fmu.api.DoStep(in.c, t, h, fmi2True), fmi2OK) << in.lastMessage();
    std::vector<double> out;
    EXPECT_EQ(in.get(names(), out), fmi2OK);
    return out;
}

TEST(MooringLineFmu, OutputsEqualTheLaw)
{
    LoadedFmu fmu("mooringLine");
    Instance in(fmu);
    ASSERT_EQ(initialise(fmu, in), fmi2OK) << in.lastMessage();
    connectors::MooringLine law(lawParameters());
    connectors::MooringLineState s = startState(law);
    const double h = 0.1;
    for (int k = 0; k < 30; ++k) {
        const double t = k * h;
        const std::vector<double> got = step(fmu, in, t, h);
        law.advance(s, floater(t + h), BodyKinematics(), h);
        const auto want = law.evaluate(s, floater(t + h), BodyKinematics(), 0);
        // the same code in two binaries: 1e-5 of the tension (as A's force)
        expectFloaterForceNear(got, want, k);
        const double T = want.fairleadTension;
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(got[std::size_t(6 + i)], want.loads.B.f_W[i], 1e-5 * T)
                << k;
        }
        EXPECT_NEAR(got[17], T, 1e-5 * T);
        EXPECT_NEAR(got[19], want.groundedLength, 1e-9);
    }
}

// The integrator choice reaches the law: CVODE (integrator 1) and
// trapezoidal substeps (maxStep 0.04 s: three a step, where the default's
// halving makes two or four) give the law's answer with the same settings,
// and differ from the default trapezoidal step per coupling step
TEST(MooringLineFmu, IntegratorParametersReachTheLaw)
{
    using Integrator = connectors::MooringLineParameters::Integrator;
    struct Case {
        std::map<std::string, double> fmu;
        Integrator integrator;
        double maxStep;
    };
    const Case cases[] = {{{{"integrator", 1.0}}, Integrator::cvode, 0.0},
                          {{{"maxStep", 0.04}}, Integrator::trapezoid, 0.04}};
    for (const Case& c : cases) {
        LoadedFmu fmu("mooringLine");
        Instance in(fmu);
        Instance byDefault(fmu);
        ASSERT_EQ(initialise(fmu, in, c.fmu), fmi2OK) << in.lastMessage();
        ASSERT_EQ(initialise(fmu, byDefault), fmi2OK);
        connectors::MooringLineParameters p = lawParameters();
        p.integrator = c.integrator;
        p.maxStep = c.maxStep;
        connectors::MooringLine law(p);
        double largestDifference = 0.0;
        besideTheLaw(
            law, 20,
            [&](int k, double t, double h, connectors::MooringLineState& s) {
                const std::vector<double> got = step(fmu, in, t, h);
                const std::vector<double> other = step(fmu, byDefault, t, h);
                law.advance(s, floater(t + h), BodyKinematics(), h);
                const double T
                    = law.evaluate(s, floater(t + h), BodyKinematics(), 0)
                          .fairleadTension;
                // the same code and doubles in two binaries (see above)
                EXPECT_NEAR(got[17], T, 1e-5 * T) << k;
                largestDifference = std::max(largestDifference,
                                             std::abs(got[17] - other[17]));
            });
        // the setting changes the answer: a wrong mapping (the parameter
        // ignored) would give the default run's tensions to the bit
        EXPECT_GT(largestDifference, 0.0);
    }
}

TEST(MooringLineFmu, RepeatedStepsEqualTheUninterruptedRun)
{
    LoadedFmu fmu("mooringLine");
    Instance once(fmu), repeated(fmu);
    ASSERT_EQ(initialise(fmu, once), fmi2OK) << once.lastMessage();
    ASSERT_EQ(initialise(fmu, repeated), fmi2OK);
    const double h = 0.05;
    // three outer correctors: two with other inputs, restored, then the
    // step itself
    ASSERT_NO_FATAL_FAILURE(expectRepeatedStepsEqual(
        fmu, once, repeated, 40, h,
        [&](Instance& in, double t) { return step(fmu, in, t, h); },
        [&](double t, int corrector) {
            BodyKinematics guess = floater(t + h);
            guess.p_WKo_W[0] += 0.2 * (corrector + 1);
            guess.v_WKo_W[2]
                -= 0.5 * (corrector + 1); // the end velocity is state too
            ASSERT_EQ(repeated.set(inputs(guess, BodyKinematics())), fmi2OK);
        }));
}

TEST(MooringLineFmu, SerializedStateContinuesInAnotherInstance)
{
    LoadedFmu fmu("mooringLine");
    Instance in(fmu);
    ASSERT_EQ(initialise(fmu, in), fmi2OK) << in.lastMessage();
    const double h = 0.1;
    for (int k = 0; k < 10; ++k) {
        step(fmu, in, k * h, h);
    }
    Instance other(fmu);
    // header + value array + count + 19 + 6 (N - 1) internal values of
    // the line and 1 + 20 (N - 1) + 4 N of its Newton matrix, 1 + 6 x 11
    // of the flow's history, 4 + 3 of the energy account (one section)
    const std::vector<fmi2Byte> bytes = restart(fmu, in, other);
    for (int k = 10; k < 20; ++k) {
        EXPECT_EQ(step(fmu, other, k * h, h), step(fmu, in, k * h, h)) << k;
    }
    // `cut` is refused: "serialized state has <its size> bytes, <why>"
    std::vector<fmi2Byte> cut;
    const auto expectRefused = [&](const std::string& why) {
        fmi2FMUstate bad = nullptr;
        EXPECT_EQ(
            fmu.api.DeSerializeFMUstate(other.c, cut.data(), cut.size(), &bad),
            fmi2Error);
        EXPECT_EQ(other.lastMessage(),
                  "fmi2DeSerializeFMUstate: serialized state has "
                      + std::to_string(cut.size()) + " bytes, " + why);
    };
    // a state of another line size does not fit
    cut.assign(bytes.begin(), bytes.end() - 6 * sizeof(double));
    expectRefused("expected " + std::to_string(bytes.size()));
    // cut within the count of the internal state, and within the values:
    // the message says where, not a size the line's state never has
    const std::size_t internalBytes = sizeof(std::uint64_t)
        + (19 + 6 * 9 + 1 + 20 * 9 + 4 * 10 + 1 + 6 * 11 + 4 + 3)
            * sizeof(double); // N = 10
    const std::size_t values = bytes.size() - internalBytes;
    cut.assign(bytes.begin(), bytes.begin() + values + 4);
    expectRefused("expected " + std::to_string(values)
                  + " without internal state, or at least "
                  + std::to_string(values + 8) + " with one");
    cut.assign(bytes.begin(), bytes.begin() + values - 8);
    expectRefused("shorter than its value array (" + std::to_string(values)
                  + " bytes)");
}

TEST(MooringLineFmu, ParameterErrorsAreNamed)
{
    LoadedFmu fmu("mooringLine");
    for (
        const auto& [name, value, message] :
        {std::tuple<std::string, double, std::string> {
             "relativeTolerance", 0.0,
             "mooringLine: parameter relativeTolerance = 0 is out of range (allowed: finite and > 0)"},
         {"segments", 2.5,
          "mooringLine: parameter segments = 2.5 is out of range (allowed: an "
          "integer from 2 to 1000)"},
         {"massPerLength", 0.0,
          "mooringLine: parameter massPerLength = 0 kg/m is out of range (allowed: "
          "finite and > 0)"},
         {"seabedContact", 2.0,
          "mooringLine: parameter seabedContact = 2 is out of range (allowed: 0 or 1)"},
         // With seabedContact = 1 the seabed would hold nothing up: the line
         // sank through it while groundedLength reported it grounded
         {"diameter", 0.0,
          "mooringLine: parameter diameter = 0 m is out of range (allowed: > 0 "
          "with seabedContact = 1: the seabed carries the line over its "
          "contact area, diameter times length)"},
         {"seabedStiffness", 0.0,
          "mooringLine: parameter seabedStiffness = 0 Pa/m is out of range "
          "(allowed: > 0 with seabedContact = 1: the seabed carries the line "
          "by its penalty stiffness)"}}) {
        Instance in(fmu);
        std::map<std::string, double> p = chainParameters;
        p[name] = value;
        EXPECT_EQ(in.initialize(p), fmi2Error);
        EXPECT_EQ(in.lastMessage(), "fmi2ExitInitializationMode: " + message);
    }
}

TEST(MooringLineFmu, LineFarShorterThanItsEndsIsRefused)
{
    // The chain's ends start 89.4 m apart (fairlead at (80, 0, 40), anchor
    // at the origin): 60 m of line would start at 49 % strain (before: it
    // ran, at 119 % on a lab line), 70 m is a taut line at 28 %
    LoadedFmu fmu("mooringLine");
    const double chord = std::hypot(80.0, 40.0);
    for (const double length : {60.0, 70.0}) {
        Instance in(fmu);
        const fmi2Status s
            = initialise(fmu, in, {{"unstretchedLength", length}});
        if (length < chord / 1.3) {
            EXPECT_EQ(s, fmi2Error);
            const std::string m = in.lastMessage();
            lawTest::expectStartsWithAndContains(
                m,
                "fmi2ExitInitializationMode: mooringLine: unstretchedLength "
                "= 60 m is out of range for the ends at the start (allowed: "
                "at least 68.8",
                "a start strain of at most 30 %)");
            // not "parameter unstretchedLength": it depends on the inputs
            EXPECT_EQ(m.find("parameter"), std::string::npos) << m;
        } else {
            EXPECT_EQ(s, fmi2OK) << in.lastMessage();
        }
    }
}

TEST(MooringLineFmu, BinaryCarriesSundials)
{
    // CVODE is linked into the binary (its local symbols are there), and
    // no SUNDIALS library is needed at run time: the FMU runs where
    // SUNDIALS is not installed
    const LoadedFmu fmu("mooringLine");
    const std::string deps = onBinary("ldd", fmu);
    ASSERT_NE(deps.find("libc.so"), std::string::npos) << deps; // ldd ran
    EXPECT_EQ(deps.find("libsundials"), std::string::npos) << deps;
    EXPECT_NE(onBinary("nm", fmu).find("CVodeCreate"), std::string::npos);
}

} // namespace

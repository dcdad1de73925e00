// mooringLine.fmu in an accelerating flow: the change of the flow inputs
// shape.Ux/Uy/Uz[k] over the previous step is the flow's acceleration the
// law takes (flowInertia = 1, the default; none at the first step); with
// flowInertia = 0 the run is that of the flow alone; with flowInertia = 2
// the inputs shape.Ax/Ay/Az[k] are the acceleration. The last step's
// flow, kept in the FMU state, makes steps repeated after fmi2SetFMUstate
// and states serialized into another instance continue bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "mooringLineFmuSupport.hpp"

namespace {

using namespace fmuTest;
using namespace mooringLineFmuTest;

std::vector<std::string> names()
{
    std::vector<std::string> n
        = {"A.F[1]", "A.F[2]", "A.F[3]", "fairleadTension", "anchorTension"};
    for (int k = 1; k <= 11; ++k) {
        n.push_back("shape.tension[" + std::to_string(k) + "]");
        n.push_back("shape.y[" + std::to_string(k) + "]");
    }
    return n;
}

//- The water at the 11 shape points at time t: a flow across the chain
//  (along y), accelerating uniformly, faster towards the fairlead
std::vector<Vector3> flowAt(double t)
{
    std::vector<Vector3> flow;
    for (int k = 0; k < 11; ++k) {
        const double a = 0.4 * (1.0 - 0.08 * k);
        flow.emplace_back(0.1, 0.2 + a * t, -0.05 * a * t);
    }
    return flow;
}

//- One coupling step from t with the flow inputs of t; the outputs
std::vector<double> step(const LoadedFmu& fmu, Instance& in, double t, double h)
{
    EXPECT_EQ(in.set(inputs(floater(t + h), BodyKinematics())), fmi2OK);
    EXPECT_EQ(in.set(flowInputs(flowAt(t))), fmi2OK);
    EXPECT_EQ(fmu.api.DoStep(in.c, t, h, fmi2True), fmi2OK) << in.lastMessage();
    std::vector<double> out;
    EXPECT_EQ(in.get(names(), out), fmi2OK);
    return out;
}

//- Parameters, then the inputs at t = 0 with the flow there
fmi2Status start(const LoadedFmu& fmu, Instance& in, double flowInertia)
{
    EXPECT_EQ(in.set(flowInputs(flowAt(0.0))), fmi2OK);
    return initialise(fmu, in, {{"flowInertia", flowInertia}});
}

TEST(MooringLineFlowInertiaFmu, AccelerationIsTheChangeOfTheFlowInputs)
{
    for (const double flowInertia : {1.0, 0.0}) {
        LoadedFmu fmu("mooringLine");
        Instance in(fmu);
        ASSERT_EQ(start(fmu, in, flowInertia), fmi2OK) << in.lastMessage();
        connectors::MooringLine law(lawParameters());
        double largestChange = 0.0;
        besideTheLaw(
            law, 30,
            [&](int k, double t, double h, connectors::MooringLineState& s) {
                const std::vector<double> got = step(fmu, in, t, h);
                const std::vector<Vector3> U = flowAt(t);
                // the change since the last step's inputs over its length
                // (none at the first step)
                std::vector<Vector3> a;
                if (k > 0 && flowInertia == 1.0) {
                    const std::vector<Vector3> before = flowAt(t - h);
                    for (std::size_t i = 0; i < U.size(); ++i) {
                        a.push_back((U[i] - before[i]) / (t - (t - h)));
                    }
                }
                law.advance(s, floater(t + h), BodyKinematics(), h, U, a);
                const auto want = law.evaluate(s, floater(t + h),
                                               BodyKinematics(), 11, U, a);
                const auto without
                    = law.evaluate(s, floater(t + h), BodyKinematics(), 11, U);
                // the same code in two binaries: 1e-5 of the tension
                expectFloaterForceNear(got, want, k);
                const double T = want.fairleadTension;
                for (int i = 0; i < 11; ++i) {
                    EXPECT_NEAR(got[std::size_t(5 + 2 * i)],
                                want.shapeTension[std::size_t(i)], 1e-5 * T)
                        << k << " " << i;
                    EXPECT_NEAR(got[std::size_t(6 + 2 * i)],
                                want.shape[std::size_t(i)][1], 1e-9)
                        << k << " " << i;
                }
                largestChange
                    = std::max(largestChange,
                               (want.loads.A.f_W - without.loads.A.f_W).norm());
            });
        if (flowInertia == 1.0) {
            // the fairlead's half segment alone takes rho A l/2 (1 + Can)
            // a_n = 1025 x 7.85e-3 x 5 x 2 x 0.4 = 32 N across the line
            EXPECT_GT(largestChange, 10.0);
        } else {
            EXPECT_EQ(largestChange, 0.0);
        }
    }
}

//- The inputs shape.Ax/Ay/Az[k] of the acceleration a at the 11 points
std::map<std::string, double> accelerationInputs(const std::vector<Vector3>& a)
{
    std::map<std::string, double> m;
    for (int k = 0; k < 11; ++k) {
        const std::string point = "[" + std::to_string(k + 1) + "]";
        for (int axis = 0; axis < 3; ++axis) {
            m[std::string("shape.A") + "xyz"[axis] + point]
                = a.empty() ? 0.0 : a[std::size_t(k)][axis];
        }
    }
    return m;
}

TEST(MooringLineFlowInertiaFmu, AccelerationInputsTakeThePlaceOfTheChange)
{
    // flowInertia = 2 given, as shape.A, the very accelerations that
    // flowInertia = 1 takes from the change of the flow inputs: the same
    // run to the bit; then shape.A of another flow: another run
    LoadedFmu fmu("mooringLine");
    Instance change(fmu), given(fmu), other(fmu);
    ASSERT_EQ(start(fmu, change, 1.0), fmi2OK) << change.lastMessage();
    ASSERT_EQ(start(fmu, given, 2.0), fmi2OK) << given.lastMessage();
    ASSERT_EQ(start(fmu, other, 2.0), fmi2OK) << other.lastMessage();
    const double h = 0.05;
    double largestDifference = 0.0;
    for (int k = 0; k < 30; ++k) {
        const double t = k * h;
        std::vector<Vector3> a;
        if (k > 0) {
            // from the previous step's time as the FMU was given it
            const double before = (k - 1) * h;
            const std::vector<Vector3> U = flowAt(t), Ub = flowAt(before);
            for (std::size_t i = 0; i < U.size(); ++i) {
                a.push_back((U[i] - Ub[i]) / (t - before));
            }
        }
        ASSERT_EQ(given.set(accelerationInputs(a)), fmi2OK);
        std::vector<Vector3> twice = a;
        for (Vector3& x : twice) {
            x *= 2.0;
        }
        ASSERT_EQ(other.set(accelerationInputs(twice)), fmi2OK);
        const std::vector<double> want = step(fmu, change, t, h);
        EXPECT_EQ(step(fmu, given, t, h), want) << k;
        const std::vector<double> o = step(fmu, other, t, h);
        largestDifference
            = std::max(largestDifference, std::abs(o[1] - want[1]));
    }
    // twice the acceleration across the line: its inertia force on the
    // fairlead's half segment alone grows by 32 N (above)
    EXPECT_GT(largestDifference, 10.0);
}

TEST(MooringLineFlowInertiaFmu, RepeatedStepsEqualTheUninterruptedRun)
{
    LoadedFmu fmu("mooringLine");
    Instance once(fmu), repeated(fmu);
    ASSERT_EQ(start(fmu, once, 1.0), fmi2OK) << once.lastMessage();
    ASSERT_EQ(start(fmu, repeated, 1.0), fmi2OK);
    const double h = 0.05;
    // outer correctors with other flow inputs: save, step, restore
    ASSERT_NO_FATAL_FAILURE(expectRepeatedStepsEqual(
        fmu, once, repeated, 30, h,
        [&](Instance& in, double t) { return step(fmu, in, t, h); },
        [&](double t, int corrector) {
            ASSERT_EQ(repeated.set(inputs(floater(t + h), BodyKinematics())),
                      fmi2OK);
            ASSERT_EQ(repeated.set(flowInputs(flowAt(t + 0.3 * corrector))),
                      fmi2OK);
        }));
}

TEST(MooringLineFlowInertiaFmu, SerializedStateContinuesInAnotherInstance)
{
    LoadedFmu fmu("mooringLine");
    Instance in(fmu);
    ASSERT_EQ(start(fmu, in, 1.0), fmi2OK) << in.lastMessage();
    const double h = 0.1;
    for (int k = 0; k < 10; ++k) {
        step(fmu, in, k * h, h);
    }
    Instance other(fmu);
    restart(fmu, in, other);
    // the first step after the restart takes the acceleration from the
    // flow saved with the state, as the uninterrupted run does
    for (int k = 10; k < 20; ++k) {
        EXPECT_EQ(step(fmu, other, k * h, h), step(fmu, in, k * h, h)) << k;
    }
}

TEST(MooringLineFlowInertiaFmu, SwitchIsDeclaredLastAndChecked)
{
    const LoadedFmu fmu("mooringLine");
    const pugi::xml_node variables
        = fmu.description.child("fmiModelDescription").child("ModelVariables");
    pugi::xml_node last;
    for (pugi::xml_node v : variables.children("ScalarVariable")) {
        last = v;
    }
    // declared after every other variable but energyAccount and the
    // acceleration inputs shape.A, declared after it in that order:
    // theirs keep their value references
    EXPECT_STREQ(last.attribute("name").value(), "shape.Az[11]");
    pugi::xml_node v = variables.first_child();
    while (v && std::string(v.attribute("name").value()) != "flowInertia") {
        v = v.next_sibling("ScalarVariable");
    }
    ASSERT_TRUE(v);
    EXPECT_STREQ(v.next_sibling("ScalarVariable").attribute("name").value(),
                 "energyAccount");
    EXPECT_STREQ(v.next_sibling("ScalarVariable")
                     .next_sibling("ScalarVariable")
                     .attribute("name")
                     .value(),
                 "shape.Ax[1]");
    last = v;
    EXPECT_STREQ(last.attribute("causality").value(), "parameter");
    EXPECT_STREQ(last.child("Real").attribute("start").value(), "1");
    LoadedFmu loaded("mooringLine");
    expectInitializationRefused(
        loaded, changed(chainParameters, {{"flowInertia", 0.5}}),
        "fmi2ExitInitializationMode: mooringLine: parameter flowInertia = 0.5 "
        "is out of range (allowed: 0, 1 or 2)");
}

} // namespace

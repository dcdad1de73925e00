// mooringLine.fmu restarted as the bridge restarts it, amid the outer
// correctors of a CFD time step: the outputs of every step after the
// restart equal the uninterrupted run's bit for bit. The bridge
// (fmuConnectorCore) saves the state at a new time step (into the state
// saved before), steps with each outer corrector's inputs, restores the
// saved state before a repeated solve, serializes the state after the
// last corrector at a write time, and on a restart sets it in a new
// instance with the body's kinematics at the restart time as inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "mooringLineFmuSupport.hpp"

namespace {

using namespace fmuTest;
using namespace mooringLineFmuTest;

//- The kinematics of body A at time t
using Motion = std::function<BodyKinematics(double)>;

//- The outputs compared after every step: the loads on both ends, the
//  fairlead tension and the energy outputs
const std::vector<std::string> compared
    = {"A.F[1]",          "A.F[2]",        "A.F[3]",       "A.M[1]",
       "A.M[2]",          "A.M[3]",        "B.F[1]",       "B.F[3]",
       "fairleadTension", "kineticEnergy", "fairleadWork", "dissipatedEnergy",
       "potentialEnergy"};

//- One CFD time step from t to t + h as the bridge takes it: the state
//  saved into `saved`, three outer correctors (the first two with A's
//  end-of-step position off by 0.2 and 0.1 mm, as a body's motion still
//  converging), each but the first restoring the saved state; the
//  outputs after the last
std::vector<double> bridgeStep(const LoadedFmu& fmu, Instance& in,
                               fmi2FMUstate& saved, const Motion& A, double t,
                               double h)
{
    EXPECT_EQ(fmu.api.GetFMUstate(in.c, &saved), fmi2OK);
    for (int corrector = 0; corrector < 3; ++corrector) {
        if (corrector > 0) {
            EXPECT_EQ(fmu.api.SetFMUstate(in.c, saved), fmi2OK);
        }
        BodyKinematics a = A(t + h);
        a.p_WKo_W[0] += 1e-4 * (2 - corrector);
        EXPECT_EQ(in.set(inputs(a, BodyKinematics())), fmi2OK);
        EXPECT_EQ(fmu.api.DoStep(in.c, t, h, fmi2True), fmi2OK)
            << in.lastMessage();
    }
    std::vector<double> out;
    EXPECT_EQ(in.get(compared, out), fmi2OK);
    return out;
}

//- `steps` steps of h from an instance set up by `initialise` and moved
//  by A, restarted after step `restartAt` in a new instance: every later
//  step's outputs equal the uninterrupted run's
using Initialise = std::function<fmi2Status(const LoadedFmu&, Instance&)>;

void expectRestartExact(const Initialise& initialise, const Motion& A, double h,
                        int restartAt, int steps)
{
    LoadedFmu fmu("mooringLine");
    Instance once(fmu), first(fmu);
    ASSERT_EQ(initialise(fmu, once), fmi2OK) << once.lastMessage();
    ASSERT_EQ(initialise(fmu, first), fmi2OK) << first.lastMessage();
    fmi2FMUstate savedOnce = nullptr, savedFirst = nullptr;
    for (int k = 0; k < restartAt; ++k) {
        bridgeStep(fmu, once, savedOnce, A, k * h, h);
        bridgeStep(fmu, first, savedFirst, A, k * h, h);
    }
    // the write: the state after the last corrector, serialized
    fmi2FMUstate written = nullptr;
    ASSERT_EQ(fmu.api.GetFMUstate(first.c, &written), fmi2OK);
    const std::vector<fmi2Byte> bytes = first.serialize(written);
    ASSERT_FALSE(bytes.empty()) << first.lastMessage();
    // the restart: a new instance, the state set, then the inputs at the
    // restart time (fmuConnectorCore::restorePending)
    Instance restarted(fmu);
    ASSERT_EQ(restarted.restore(bytes), fmi2OK) << restarted.lastMessage();
    ASSERT_EQ(restarted.set(inputs(A(restartAt * h), BodyKinematics())),
              fmi2OK);
    fmi2FMUstate savedRestarted = nullptr;
    for (int k = restartAt; k < steps; ++k) {
        const std::vector<double> want
            = bridgeStep(fmu, once, savedOnce, A, k * h, h);
        ASSERT_EQ(bridgeStep(fmu, restarted, savedRestarted, A, k * h, h), want)
            << "step " << k << " after a restart at step " << restartAt;
    }
    EXPECT_EQ(fmu.api.FreeFMUstate(once.c, &savedOnce), fmi2OK);
    EXPECT_EQ(fmu.api.FreeFMUstate(first.c, &savedFirst), fmi2OK);
    EXPECT_EQ(fmu.api.FreeFMUstate(first.c, &written), fmi2OK);
    EXPECT_EQ(fmu.api.FreeFMUstate(restarted.c, &savedRestarted), fmi2OK);
}

TEST(MooringLineRestartFmu, ChainOnTheSeabedRestartsExactly)
{
    // The 100 m chain of the FMU tests, partly on the seabed, its floater
    // surging and heaving; 0.1 s steps, restarted at 2 s
    expectRestartExact(
        [](const LoadedFmu& fmu, Instance& in) { return initialise(fmu, in); },
        floater, 0.1, 20, 60);
}

//- The lab chain's fairlead (labChainParameters) surging 0.112 m at 1 Hz
//  from rest, lifting the chain off and snapping it taut every cycle: the
//  steps that halve and those that iterate Newton further
BodyKinematics labChainFairlead(double t)
{
    constexpr double pi = 3.14159265358979323846;
    const double w = 2.0 * pi, a = 0.112;
    const double ramp = t < 1.0 ? 0.5 * (1.0 - std::cos(pi * t)) : 1.0;
    const double rate = t < 1.0 ? 0.5 * pi * std::sin(pi * t) : 0.0;
    BodyKinematics k;
    k.p_WKo_W = Vector3(-a * ramp * std::sin(w * t), 0.0, -0.05);
    k.v_WKo_W = Vector3(
        -a * (rate * std::sin(w * t) + ramp * w * std::cos(w * t)), 0.0, 0.0);
    return k;
}

TEST(MooringLineRestartFmu, SnappingLabChainRestartsExactly)
{
    // 1 ms steps (the moored tutorials' first), restarted at 1.5 s, just
    // before a snap, and compared over the next 0.5 s
    expectRestartExact(
        [](const LoadedFmu& fmu, Instance& in) {
            fmi2Status s = fmu.api.EnterInitializationMode(in.c);
            if (s == fmi2OK) {
                s = in.set(labChainParameters);
            }
            if (s == fmi2OK) {
                s = in.set(inputs(labChainFairlead(0.0), BodyKinematics()));
            }
            return s == fmi2OK ? fmu.api.ExitInitializationMode(in.c) : s;
        },
        labChainFairlead, 1e-3, 1500, 2000);
}

} // namespace

// Fixtures of the mooringLine.fmu tests: a 100 m chain moored 80 m from
// its anchor in 40 m of water, its parameters for the FMU and for the
// law, the floater that moves it, and the FMU's initialisation.
#ifndef TESTS_FMU_MOORINGLINEFMUSUPPORT_HPP
#define TESTS_FMU_MOORINGLINEFMUSUPPORT_HPP

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ConnectorInputs.hpp"
#include "MooringLineReferences.hpp"
#include "mooringLine/MooringLine.hpp"

namespace mooringLineFmuTest {

using fmuTest::BodyKinematics;
using fmuTest::Vector3;

inline const std::map<std::string, double> chainParameters
    = {{"unstretchedLength", 100.0},
       {"EA", 5e7},
       {"axialDamping", 2e5},
       {"massPerLength", 80.0},
       {"diameter", 0.1},
       {"normalDrag", 1.2},
       {"tangentialDrag", 0.05},
       {"normalAddedMass", 1.0},
       {"seabedContact", 1.0},
       {"segments", 10.0},
       {"A.p[3]", -2.0},
       {"B.p[1]", 0.0}}; // the anchor at B's reference point

//- The lab chain (tests/connectors/MooringLineReferences.hpp: 1.2 m in
//  0.5 m of water, on the seabed), its anchor 1 m from A's reference
//  point and 0.5 m below it
inline const std::map<std::string, double> labChainParameters
    = {{"unstretchedLength", 1.2},
       {"EA", 3.416e5},
       {"axialDamping", 2.473},
       {"massPerLength", 0.0796},
       {"diameter", 3.6e-3},
       {"normalDrag", 1.33},
       {"tangentialDrag", 0.2},
       {"normalAddedMass", 1.0},
       {"tangentialAddedMass", 0.5},
       {"seabedContact", 1.0},
       {"seabedStiffness", 3e5},
       {"seabedDamping", 3e3},
       {"B.p[1]", -1.0},
       {"B.p[3]", -0.5}};

inline connectors::MooringLineParameters lawParameters()
{
    connectors::MooringLineParameters p = connectors::references::chain100(10);
    p.p_AoP_A = Vector3(0, 0, -2.0);
    return p;
}

//- A body surging and heaving 80 m from the anchor in 40 m of water
inline BodyKinematics floater(double t)
{
    return fmuTest::kinematics(
        Vector3(80.0 + 3.0 * std::sin(0.5 * t), 0.0, 42.0 + std::sin(t)), 0.0,
        Vector3(0, 0, 1), Vector3(1.5 * std::cos(0.5 * t), 0.0, std::cos(t)),
        Vector3::Zero());
}

//- Parameters, then the inputs at t = 0 (the start shape depends on them)
inline fmi2Status initialise(const fmuTest::LoadedFmu& fmu,
                             fmuTest::Instance& in,
                             const std::map<std::string, double>& extra = {})
{
    fmi2Status s = fmu.api.EnterInitializationMode(in.c);
    if (s == fmi2OK) {
        s = in.set(chainParameters);
    }
    if (s == fmi2OK && !extra.empty()) {
        s = in.set(extra);
    }
    if (s == fmi2OK) {
        s = in.set(fmuTest::inputs(floater(0.0), BodyKinematics()));
    }
    return s == fmi2OK ? fmu.api.ExitInitializationMode(in.c) : s;
}

//- The law's state at the start of the FMU's run: the floater at t = 0,
//  the anchor at the origin
inline connectors::MooringLineState
startState(const connectors::MooringLine& law)
{
    return law.initialState(floater(0.0), BodyKinematics(), 0.0);
}

//- `steps` coupling steps of h = 0.1 s from t = 0 of `law` from its start
//  state beside an FMU instance: step(k, t, h, s) takes step k of both,
//  s the law's state; stops at the first fatal failure
template <class Step>
void besideTheLaw(connectors::MooringLine& law, int steps, Step&& step)
{
    connectors::MooringLineState s = startState(law);
    const double h = 0.1;
    for (int k = 0; k < steps; ++k) {
        ASSERT_NO_FATAL_FAILURE(step(k, k * h, h, s));
    }
}

//- The force on the floater `got[0..2]` equals the law's `want` at step
//  `k`: the same code on the same doubles compiled into two binaries, so
//  only instruction selection (FMA contraction) may differ, and CVODE
//  amplifies such round-off at most to its tolerance (1e-6): 1e-5 of the
//  fairlead tension is ample
template <class Result>
void expectFloaterForceNear(const std::vector<double>& got, const Result& want,
                            int k)
{
    const double T = want.fairleadTension;
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(got[std::size_t(i)], want.loads.A.f_W[i], 1e-5 * T) << k;
    }
}

//- `steps` coupling steps of `h` from t = 0 of `once` and of `repeated`,
//  each of `repeated`'s after two outer correctors (save the state, set
//  the corrector's inputs with `setCorrectorInputs(t, corrector)`, step,
//  restore): `step(in, t)` gives the outputs of both bit for bit
template <class Step, class SetCorrectorInputs>
void expectRepeatedStepsEqual(const fmuTest::LoadedFmu& fmu,
                              fmuTest::Instance& once,
                              fmuTest::Instance& repeated, int steps, double h,
                              Step&& step,
                              SetCorrectorInputs&& setCorrectorInputs)
{
    fmi2FMUstate saved = nullptr;
    for (int k = 0; k < steps; ++k) {
        const double t = k * h;
        const std::vector<double> reference = step(once, t);
        ASSERT_EQ(fmu.api.GetFMUstate(repeated.c, &saved), fmi2OK);
        for (int corrector = 0; corrector < 2; ++corrector) {
            ASSERT_NO_FATAL_FAILURE(setCorrectorInputs(t, corrector));
            ASSERT_EQ(fmu.api.DoStep(repeated.c, t, h, fmi2True), fmi2OK);
            ASSERT_EQ(fmu.api.SetFMUstate(repeated.c, saved), fmi2OK);
        }
        EXPECT_EQ(step(repeated, t), reference) << "step " << k;
    }
    EXPECT_EQ(fmu.api.FreeFMUstate(repeated.c, &saved), fmi2OK);
}

//- Water velocities at the 11 shape points, point 1 at the fairlead, as
//  the inputs shape.Ux/Uy/Uz[k]
inline std::map<std::string, double>
flowInputs(const std::vector<Vector3>& flow)
{
    std::map<std::string, double> m;
    for (int k = 0; k < 11; ++k) {
        const std::string point = "[" + std::to_string(k + 1) + "]";
        m["shape.Ux" + point] = flow[std::size_t(k)][0];
        m["shape.Uy" + point] = flow[std::size_t(k)][1];
        m["shape.Uz" + point] = flow[std::size_t(k)][2];
    }
    return m;
}

//- A restart: the state of `from` serialized and set in `to` (a new
//  instance, no parameters set); the serialized bytes
inline std::vector<fmi2Byte> restart(const fmuTest::LoadedFmu& fmu,
                                     fmuTest::Instance& from,
                                     fmuTest::Instance& to)
{
    fmi2FMUstate saved = nullptr;
    EXPECT_EQ(fmu.api.GetFMUstate(from.c, &saved), fmi2OK);
    const std::vector<fmi2Byte> bytes = from.serialize(saved);
    EXPECT_FALSE(bytes.empty()) << from.lastMessage();
    EXPECT_EQ(to.restore(bytes), fmi2OK) << to.lastMessage();
    EXPECT_EQ(fmu.api.FreeFMUstate(from.c, &saved), fmi2OK);
    return bytes;
}

} // namespace mooringLineFmuTest

#endif

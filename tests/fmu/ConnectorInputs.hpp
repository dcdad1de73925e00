// Connector FMU inputs and parameters for the FMU tests, built from the
// law library's structs so that FMU outputs can be compared with the law.
#ifndef TESTS_FMU_CONNECTORINPUTS_HPP
#define TESTS_FMU_CONNECTORINPUTS_HPP

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "FmuHarness.hpp"
#include "common/Kinematics.hpp"

namespace fmuTest {

using connectors::BodyKinematics;
using connectors::Matrix3;
using connectors::Vector3;

inline void addVector(std::map<std::string, double>& m, const std::string& name,
                      const Vector3& v)
{
    for (int i = 0; i < 3; ++i) {
        m[name + "[" + std::to_string(i + 1) + "]"] = v[i];
    }
}

//- name[i,j] = m(i - 1, j - 1), as the FMUs name a 3x3 variable
inline void addMatrix(std::map<std::string, double>& m, const std::string& name,
                      const Matrix3& value)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            m[name + "[" + std::to_string(i + 1) + "," + std::to_string(j + 1)
              + "]"]
                = value(i, j);
        }
    }
}

//- FMU input values (A.r ... B.omega) for the given kinematics
inline std::map<std::string, double> inputs(const BodyKinematics& A,
                                            const BodyKinematics& B)
{
    std::map<std::string, double> m;
    for (const auto& [prefix, k] :
         {std::pair<std::string, const BodyKinematics&> {"A", A},
          std::pair<std::string, const BodyKinematics&> {"B", B}}) {
        addVector(m, prefix + ".r", k.p_WKo_W);
        addVector(m, prefix + ".v", k.v_WKo_W);
        addVector(m, prefix + ".omega", k.w_WK_W);
        addMatrix(m, prefix + ".R", k.R_WK);
    }
    return m;
}

inline BodyKinematics kinematics(const Vector3& r, double angle,
                                 const Vector3& axis, const Vector3& v,
                                 const Vector3& omega)
{
    BodyKinematics k;
    k.p_WKo_W = r;
    k.R_WK = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    k.v_WKo_W = v;
    k.w_WK_W = omega;
    return k;
}

//- A generic, non-degenerate configuration: rotated, moving bodies
inline BodyKinematics genericA()
{
    return kinematics(Vector3(0.2, -0.4, 1.1), 0.6, Vector3(1, -2, 0.5),
                      Vector3(0.3, 0.1, -0.2), Vector3(0.05, -0.3, 0.2));
}

inline BodyKinematics genericB()
{
    return kinematics(Vector3(1.9, 0.7, 0.4), -1.3, Vector3(0.2, 1, 1),
                      Vector3(-0.6, 0.4, 0.25), Vector3(-0.1, 0.2, 0.4));
}

//- Parameters of the FMU with non-zero, non-special values (only those
//  the FMU declares). The lines' unstretchedLength exceeds the 2.57 m
//  between the generic attachment points (mooringLine refuses to start a
//  line stretched beyond 30 %)
//- The attachment points of genericParameters: A.p and B.p [m]
inline const Vector3 genericAp(0.1, -0.2, 0.3), genericBp(-0.4, 0.05, 0.2);

inline std::map<std::string, double> genericParameters(const LoadedFmu& fmu)
{
    std::map<std::string, double> all = {{"stiffness", 250.0},
                                         {"restLength", 0.7},
                                         {"damping", 15.0},
                                         {"unstretchedLength", 3.0}};
    addVector(all, "A.p", genericAp);
    addVector(all, "B.p", genericBp);
    std::map<std::string, double> declared;
    for (const auto& [name, value] : all) {
        if (fmu.vr.count(name)) {
            declared[name] = value;
        }
    }
    return declared;
}

//- Parameters of a two-point law with the attachment points of
//  genericParameters
template <class Parameters> Parameters genericallyAttached()
{
    Parameters p;
    p.p_AoP_A = genericAp;
    p.p_BoQ_B = genericBp;
    return p;
}

//- The 17 interface outputs of a law result, in connectorOutputs() order
inline std::vector<double> flatten(const connectors::ConnectorResult& r)
{
    return {r.A.f_W[0],       r.A.f_W[1],    r.A.f_W[2],    r.A.m_Ko_W[0],
            r.A.m_Ko_W[1],    r.A.m_Ko_W[2], r.B.f_W[0],    r.B.f_W[1],
            r.B.f_W[2],       r.B.m_Ko_W[0], r.B.m_Ko_W[1], r.B.m_Ko_W[2],
            r.length,         r.lengthRate,  r.tension,     r.potentialEnergy,
            r.dissipatedPower};
}

//- The FMU's outputs `names` equal `want`
inline void expectOutputs(Instance& in, const std::vector<std::string>& names,
                          const std::vector<double>& want)
{
    std::vector<double> got;
    ASSERT_EQ(in.get(names, got), fmi2OK) << in.lastMessage();
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        // Tolerance: the FMU runs the same law on the same doubles; only
        // a different instruction order in the two builds (contraction,
        // inlining) can change the last bits: 1e-13 relative.
        EXPECT_NEAR(got[i], want[i], 1e-13 * (1.0 + std::abs(want[i])))
            << names[i];
    }
}

//- `parameters` with `changes` set over them
inline std::map<std::string, double>
changed(std::map<std::string, double> parameters,
        const std::map<std::string, double>& changes)
{
    for (const auto& [name, value] : changes) {
        parameters[name] = value;
    }
    return parameters;
}

//- A new instance of `fmu` initialised with `parameters` fails with
//  fmi2Error and `message`
inline void
expectInitializationRefused(const LoadedFmu& fmu,
                            const std::map<std::string, double>& parameters,
                            const std::string& message)
{
    Instance in(fmu);
    EXPECT_EQ(in.initialize(parameters), fmi2Error);
    EXPECT_EQ(in.lastMessage(), message);
}

//- The FMU's interface outputs equal the law's result
inline void expectOutputs(Instance& in,
                          const connectors::ConnectorResult& expected)
{
    expectOutputs(in, connectorOutputs(), flatten(expected));
}

//- `in` stepped from 0 to 0.01 with the inputs (genericA, genericB), then
//  to 0.02 with the bodies swapped, and after each step
//  `expectOutputsFor(A, B)` with the inputs of that step
template <class Expect>
void stepBothWays(const LoadedFmu& fmu, Instance& in, Expect&& expectOutputsFor)
{
    ASSERT_EQ(in.set(inputs(genericA(), genericB())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.01, fmi2True), fmi2OK);
    expectOutputsFor(genericA(), genericB());
    ASSERT_EQ(in.set(inputs(genericB(), genericA())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.01, 0.02, fmi2True), fmi2OK);
    expectOutputsFor(genericB(), genericA());
}

} // namespace fmuTest

#endif

// Same answers: every connector's FMI 3.0 FMU and FMI 2.0 FMU, given the
// same parameters and the same inputs over a short run, return bitwise
// identical outputs at every step (every output element, through the
// mapping of names of docs/connector-fmu-interface.md).
#include <cmath>
#include <cstring>

#include "ConnectorFmuTest.hpp"
#include "ConnectorInputs.hpp"
#include "Fmi3Harness.hpp"

namespace {

using namespace fmuTest;

class Fmi3SameAnswers : public ConnectorFmu { };

//- Bodies moving on a short, smooth path around the generic configuration
std::map<std::string, double> inputsAt(double t)
{
    const double s = std::sin(3.0 * t);
    const double c = std::cos(2.0 * t);
    const BodyKinematics A = kinematics(
        Vector3(0.2 + 0.05 * s, -0.4, 1.1 - 0.03 * c), 0.6 + 0.1 * s,
        Vector3(1, -2, 0.5), Vector3(0.15 * c, 0.1, -0.2 * s),
        Vector3(0.05, -0.3, 0.2));
    const BodyKinematics B = kinematics(
        Vector3(1.9, 0.7 + 0.04 * c, 0.4 + 0.02 * s), -1.3, Vector3(0.2, 1, 1),
        Vector3(-0.6, 0.4 * s, 0.25), Vector3(-0.1, 0.2, 0.4 * c));
    return inputs(A, B);
}

TEST_P(Fmi3SameAnswers, BitwiseIdenticalOutputs)
{
    const LoadedFmu3 fmu3(GetParam());
    Instance in2(*fmu);
    Instance3 in3(fmu3);
    ASSERT_NE(in2.c, nullptr);
    ASSERT_NE(in3.c, nullptr) << in3.lastMessage();
    const std::map<std::string, double> parameters = genericParameters(*fmu);
    ASSERT_EQ(in2.initialize(parameters), fmi2OK) << in2.lastMessage();
    ASSERT_EQ(in3.initialize(arrayValues(parameters, fmu3)), fmi3OK)
        << in3.lastMessage();

    // Every output element, in FMI 2.0 names and in FMI 3.0 order
    std::vector<std::string> names2;
    std::vector<std::string> outputs3;
    for (const Variable3& v : fmu3.variables) {
        if (v.causality == fmuImport::Causality::output) {
            outputs3.push_back(v.name);
            for (const std::string& name : fmi2ElementNames(v)) {
                names2.push_back(name);
            }
        }
    }
    ASSERT_FALSE(names2.empty());

    const double h = 0.05;
    for (int k = 0; k < 10; ++k) {
        const double t = k * h;
        const std::map<std::string, double> u = inputsAt(t + h);
        ASSERT_EQ(in2.set(u), fmi2OK);
        ASSERT_EQ(in3.set(arrayValues(u, fmu3)), fmi3OK);
        ASSERT_EQ(fmu->api.DoStep(in2.c, t, h, fmi2True), fmi2OK)
            << in2.lastMessage();
        ASSERT_EQ(in3.doStep(t, h), fmi3OK) << in3.lastMessage();

        std::vector<double> values2;
        ASSERT_EQ(in2.get(names2, values2), fmi2OK);
        std::vector<double> values3;
        for (const std::string& name : outputs3) {
            const std::vector<double> v = in3.get(name);
            values3.insert(values3.end(), v.begin(), v.end());
        }
        ASSERT_EQ(values3.size(), values2.size());
        for (std::size_t i = 0; i < values2.size(); ++i) {
            EXPECT_EQ(std::memcmp(&values2[i], &values3[i], sizeof(double)), 0)
                << names2[i] << " at t = " << t + h << ": " << values2[i]
                << " (FMI 2.0) and " << values3[i] << " (FMI 3.0)";
        }
    }
}

FMU_TEST_INSTANTIATE(Fmi3SameAnswers);

} // namespace

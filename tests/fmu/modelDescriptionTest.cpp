// What the FMI 2.0 schema cannot check in each connector's generated
// modelDescription.xml: unique names and value references, start values,
// units, the variables of the connector interface, <ModelStructure>, and
// (numerically) that every observed input -> output dependency is declared.
#include <cmath>
#include <set>
#include <sstream>

#include "ConnectorFmuTest.hpp"
#include "ConnectorInputs.hpp"

namespace {

using namespace fmuTest;

class ModelDescription : public ConnectorFmu {
protected:
    pugi::xml_node root() const
    {
        return fmu->description.child("fmiModelDescription");
    }

    std::vector<pugi::xml_node> variables() const
    {
        std::vector<pugi::xml_node> v;
        for (const pugi::xml_node n :
             root().child("ModelVariables").children("ScalarVariable")) {
            v.push_back(n);
        }
        return v;
    }

    //- Unknown index -> dependency indices, for <Outputs> or <InitialUnknowns>
    std::map<int, std::set<int>> unknowns(const char* list) const
    {
        std::map<int, std::set<int>> m;
        for (const pugi::xml_node u :
             root().child("ModelStructure").child(list).children("Unknown")) {
            EXPECT_TRUE(u.attribute("dependencies"))
                << "index " << u.attribute("index").value();
            std::istringstream deps(u.attribute("dependencies").value());
            std::set<int>& d = m[u.attribute("index").as_int()];
            for (int i = 0; deps >> i;) {
                d.insert(i);
            }
        }
        return m;
    }
};

TEST_P(ModelDescription, NamesAndValueReferencesAreUnique)
{
    std::set<std::string> names;
    std::set<unsigned> refs;
    for (const pugi::xml_node v : variables()) {
        EXPECT_TRUE(names.insert(v.attribute("name").value()).second)
            << v.attribute("name").value();
        EXPECT_TRUE(
            refs.insert(v.attribute("valueReference").as_uint()).second);
    }
    EXPECT_EQ(names.size(), fmu->vr.size());
}

TEST_P(ModelDescription, StartValuesUnitsAndDescriptions)
{
    std::set<std::string> declared;
    for (const pugi::xml_node u :
         root().child("UnitDefinitions").children("Unit")) {
        declared.insert(u.attribute("name").value());
        EXPECT_TRUE(u.child("BaseUnit")) << u.attribute("name").value();
    }
    for (const pugi::xml_node v : variables()) {
        const std::string name = v.attribute("name").value();
        const std::string causality = v.attribute("causality").value();
        EXPECT_FALSE(std::string(v.attribute("description").value()).empty())
            << name;
        const std::string variability = v.attribute("variability").value();
        if (causality == "local" && variability == "constant") {
            // inputsStartAtRest: Boolean, with a start value
            EXPECT_TRUE(v.child("Boolean").attribute("start")) << name;
            continue;
        }
        const pugi::xml_node real = v.child("Real");
        ASSERT_TRUE(real) << name;
        if (causality == "input" || causality == "parameter") {
            EXPECT_TRUE(real.attribute("start")) << name;
        } else {
            // outputs and the continuous locals of line FMUs: calculated
            EXPECT_TRUE(causality == "output" || causality == "local") << name;
            EXPECT_EQ(std::string(v.attribute("initial").value()), "calculated")
                << name;
            EXPECT_FALSE(real.attribute("start")) << name;
        }
        EXPECT_EQ(declared.count(real.attribute("unit").value()), 1u) << name;
    }
}

TEST_P(ModelDescription, InterfaceVariables)
{
    // docs/connector-fmu-interface.md: required names, causality and units
    std::map<std::string, std::pair<std::string, std::string>> expected;
    for (const std::string body : {"A", "B"}) {
        for (int i = 1; i <= 3; ++i) {
            const std::string k = "[" + std::to_string(i) + "]";
            expected[body + ".r" + k] = {"input", "m"};
            expected[body + ".v" + k] = {"input", "m/s"};
            expected[body + ".omega" + k] = {"input", "rad/s"};
            expected[body + ".p" + k] = {"parameter", "m"};
            expected[body + ".F" + k] = {"output", "N"};
            expected[body + ".M" + k] = {"output", "N.m"};
            for (int j = 1; j <= 3; ++j) {
                expected[body + ".R[" + std::to_string(i) + ","
                         + std::to_string(j) + "]"]
                    = {"input", "1"};
            }
        }
    }
    expected["length"] = {"output", "m"};
    expected["lengthRate"] = {"output", "m/s"};
    expected["tension"] = {"output", "N"};
    expected["potentialEnergy"] = {"output", "J"};
    expected["dissipatedPower"] = {"output", "W"};
    std::map<std::string, pugi::xml_node> byName;
    for (const pugi::xml_node v : variables()) {
        byName[v.attribute("name").value()] = v;
    }
    for (const auto& [name, cu] : expected) {
        // Required: A.r, A.R, A.F, A.M, and the same for B in a two-body
        // connector; everything else is checked when declared.
        const bool twoBody = byName.count("B.r[1]") == 1;
        const std::string head = name.substr(0, 3);
        const bool required = head == "A.r" || head == "A.R" || head == "A.F"
            || head == "A.M"
            || (twoBody
                && (head == "B.r" || head == "B.R" || head == "B.F"
                    || head == "B.M"));
        if (!required && byName.count(name) == 0) {
            continue;
        }
        ASSERT_EQ(byName.count(name), 1u) << name;
        EXPECT_EQ(std::string(byName[name].attribute("causality").value()),
                  cu.first)
            << name;
        EXPECT_EQ(
            std::string(byName[name].child("Real").attribute("unit").value()),
            cu.second)
            << name;
    }
    const pugi::xml_node cs = root().child("CoSimulation");
    EXPECT_EQ(std::string(cs.attribute("modelIdentifier").value()), fmu->name);
    EXPECT_TRUE(
        cs.attribute("canHandleVariableCommunicationStepSize").as_bool());
    EXPECT_TRUE(cs.attribute("canGetAndSetFMUstate").as_bool());
    EXPECT_TRUE(cs.attribute("canSerializeFMUstate").as_bool());
    EXPECT_TRUE(cs.attribute("canNotUseMemoryManagementFunctions").as_bool());
    EXPECT_EQ(std::string(root().attribute("variableNamingConvention").value()),
              "structured");
}

TEST_P(ModelDescription, ModelStructureListsEveryOutput)
{
    const std::vector<pugi::xml_node> vars = variables();
    std::set<int> outputs;
    for (std::size_t i = 0; i < vars.size(); ++i) {
        if (std::string(vars[i].attribute("causality").value()) == "output") {
            outputs.insert(int(i + 1));
        }
    }
    const auto causality = [&](int index) {
        return std::string(
            vars.at(std::size_t(index - 1)).attribute("causality").value());
    };
    const std::map<int, std::set<int>> out = unknowns("Outputs");
    const std::map<int, std::set<int>> initial = unknowns("InitialUnknowns");
    std::set<int> listed, listedInitial;
    for (const auto& [index, deps] : out) {
        listed.insert(index);
        for (const int d : deps) {
            EXPECT_EQ(causality(d), "input")
                << "Outputs: " << index << " on " << d;
        }
    }
    for (const auto& [index, deps] : initial) {
        listedInitial.insert(index);
        for (const int d : deps) {
            const std::string c = causality(d);
            EXPECT_TRUE(c == "input" || c == "parameter")
                << index << " on " << d;
        }
    }
    EXPECT_EQ(listed, outputs);
    EXPECT_EQ(listedInitial, outputs);
}

TEST_P(ModelDescription, ObservedDependenciesAreDeclared)
{
    // Perturb each input (stepComplete, against <Outputs>) and each
    // parameter (initialization mode, against <InitialUnknowns>) and check
    // that every output that moves declares that dependency; also every
    // input must move some output (a connector declares only what it reads).
    const std::vector<pugi::xml_node> vars = variables();
    const std::map<int, std::set<int>> declaredOut = unknowns("Outputs");
    const std::map<int, std::set<int>> declaredInit
        = unknowns("InitialUnknowns");
    const std::map<std::string, double> base = inputs(genericA(), genericB());
    const std::map<std::string, double> parameters = genericParameters(*fmu);
    std::map<std::string, int> indexOf; // 1-based position in ModelVariables
    for (std::size_t i = 0; i < vars.size(); ++i) {
        indexOf[vars[i].attribute("name").value()] = int(i + 1);
    }
    const auto observe = [&](bool initMode, const std::string& name,
                             double delta) {
        Instance in(*fmu);
        EXPECT_EQ(fmu->api.EnterInitializationMode(in.c), fmi2OK);
        EXPECT_EQ(in.set(parameters), fmi2OK);
        EXPECT_EQ(in.set(base), fmi2OK);
        if (!initMode) {
            EXPECT_EQ(fmu->api.ExitInitializationMode(in.c), fmi2OK);
        }
        std::vector<double> before, after;
        EXPECT_EQ(in.get(connectorOutputs(), before), fmi2OK);
        EXPECT_EQ(
            in.set({{name, (initMode ? parameters : base).at(name) + delta}}),
            fmi2OK);
        EXPECT_EQ(in.get(connectorOutputs(), after), fmi2OK);
        std::set<std::string> moved;
        for (std::size_t i = 0; i < before.size(); ++i) {
            // A perturbation of 1e-3 moves a dependent output by ~1e-3
            // times an O(1..100) gradient; 1e-12 relative is round-off.
            if (std::abs(after[i] - before[i])
                > 1e-12 * (1.0 + std::abs(before[i]))) {
                moved.insert(connectorOutputs()[i]);
            }
        }
        return moved;
    };
    for (const auto& [name, value] : base) {
        const std::set<std::string> moved = observe(false, name, 1e-3);
        EXPECT_FALSE(moved.empty()) << name << " moves no output";
        for (const std::string& output : moved) {
            EXPECT_EQ(
                declaredOut.at(indexOf.at(output)).count(indexOf.at(name)), 1u)
                << output << " depends on " << name;
        }
    }
    for (const auto& [name, value] : parameters) {
        for (const std::string& output : observe(true, name, 1e-3)) {
            EXPECT_EQ(
                declaredInit.at(indexOf.at(output)).count(indexOf.at(name)), 1u)
                << output << " depends on " << name;
        }
    }
}

// Body B's inputs start as the world the bridge feeds a connector without a
// bodyB: at the origin, identity orientation, at rest; so a tool that
// leaves them at their start values (fmusim run) has B.p as the anchor in
// global coordinates, and the start values without load (a spring at its
// rest length) come from the parameters
TEST_P(ModelDescription, BodyBStartsAsTheWorld)
{
    std::map<std::string, double> start;
    for (const pugi::xml_node v : variables()) {
        const pugi::xml_node real = v.child("Real");
        if (real.attribute("start")) {
            start[v.attribute("name").value()]
                = real.attribute("start").as_double();
        }
    }
    if (start.count("B.r[1]") == 0) {
        GTEST_SKIP() << "no body B";
    }
    for (int i = 1; i <= 3; ++i) {
        const std::string k = "[" + std::to_string(i) + "]";
        for (const char* name : {"B.r", "B.v", "B.omega"}) {
            ASSERT_EQ(start.count(name + k), 1u) << name << k;
            EXPECT_EQ(start[name + k], 0.0) << name << k;
        }
        for (int j = 1; j <= 3; ++j) {
            const std::string R
                = "B.R[" + std::to_string(i) + "," + std::to_string(j) + "]";
            ASSERT_EQ(start.count(R), 1u) << R;
            EXPECT_EQ(start[R], i == j ? 1.0 : 0.0) << R;
        }
    }
}

FMU_TEST_INSTANTIATE(ModelDescription);

} // namespace

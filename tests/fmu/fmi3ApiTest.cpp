// Every connector as an FMI 3.0 co-simulation FMU through its C entry
// points: instantiation (token checked, co-simulation only), arrays in
// fmi3Get/SetFloat64 (nValues, element value references refused), step,
// FMU states (get/set, serialization, the bytes of the 2.0 FMU), and
// functions that do not apply (fmi3Error with a logged reason).
#include <cstring>

#include "ConnectorFmuTest.hpp"
#include "ConnectorInputs.hpp"
#include "Fmi3Harness.hpp"

namespace {

using namespace fmuTest;

class Fmi3Functions : public ConnectorFmu {
protected:
    void SetUp() override
    {
        ConnectorFmu::SetUp();
        fmu3 = std::make_unique<LoadedFmu3>(GetParam());
    }

    //- Initialised with generic parameters and inputs, stepped once
    void prepare(Instance3& in)
    {
        ASSERT_NE(in.c, nullptr) << in.lastMessage();
        ASSERT_EQ(in.initialize(arrayValues(genericParameters(*fmu), *fmu3)),
                  fmi3OK)
            << in.lastMessage();
        ASSERT_EQ(in.set(arrayValues(inputs(genericA(), genericB()), *fmu3)),
                  fmi3OK)
            << in.lastMessage();
        ASSERT_EQ(in.doStep(0.0, 0.5), fmi3OK) << in.lastMessage();
    }

    std::vector<double> outputs(Instance3& in)
    {
        std::vector<double> all;
        for (const Variable3& v : fmu3->variables) {
            if (v.causality == fmuImport::Causality::output) {
                const std::vector<double> values = in.get(v.name);
                all.insert(all.end(), values.begin(), values.end());
            }
        }
        return all;
    }

    std::unique_ptr<LoadedFmu3> fmu3;
};

TEST_P(Fmi3Functions, ExportsTheFunctions)
{
    EXPECT_TRUE(fmu3->missing.empty()) << fmu3->missing.front();
    EXPECT_STREQ(fmu3->api.GetVersion(), "3.0");
}

TEST_P(Fmi3Functions, InstantiationChecksTokenAndInterface)
{
    Instance3 wrong(*fmu3, "{00000000-0000-0000-0000-000000000000}");
    EXPECT_EQ(wrong.c, nullptr);
    ASSERT_FALSE(wrong.log.empty());
    EXPECT_NE(wrong.lastMessage().find("does not match"), std::string::npos)
        << wrong.lastMessage();

    std::vector<LogRecord3> log;
    EXPECT_EQ(fmu3->api.InstantiateModelExchange(
                  "me", fmu3->token.c_str(), nullptr, false, false, &log,
                  [](fmi3InstanceEnvironment env, fmi3Status s, fmi3String c,
                     fmi3String m) {
                      static_cast<std::vector<LogRecord3>*>(env)->push_back(
                          {s, c, m});
                  }),
              nullptr);
    ASSERT_EQ(log.size(), 1u);
    EXPECT_NE(log[0].message.find("co-simulation only"), std::string::npos);
}

TEST_P(Fmi3Functions, StepsAndReadsArrays)
{
    Instance3 in(*fmu3);
    prepare(in);
    const std::vector<double> F = in.get("A.F");
    ASSERT_EQ(F.size(), 3u);
    const std::vector<double> R = in.get("A.R");
    ASSERT_EQ(R.size(), 9u);
    // Row-major: A.R[1,2] is element 1
    EXPECT_EQ(R[1], genericA().R_WK(0, 1));
    EXPECT_EQ(in.get("B.r")[2], genericB().p_WKo_W[2]);
    // Two arrays in one call
    const fmi3ValueReference both[] = {fmu3->variable("A.F").valueReference,
                                       fmu3->variable("B.F").valueReference};
    double values[6];
    ASSERT_EQ(fmu3->api.GetFloat64(in.c, both, 2, values, 6), fmi3OK);
    EXPECT_EQ(std::vector<double>(values, values + 3), F);
    EXPECT_EQ(in.doStep(0.5, 0.25), fmi3OK) << in.lastMessage();
    EXPECT_EQ(fmu3->api.Terminate(in.c), fmi3OK);
}

TEST_P(Fmi3Functions, RefusesWrongValueCountsAndElementReferences)
{
    Instance3 in(*fmu3);
    prepare(in);
    const fmi3ValueReference F = fmu3->variable("A.F").valueReference;
    double values[4] = {0, 0, 0, 0};
    EXPECT_EQ(fmu3->api.GetFloat64(in.c, &F, 1, values, 4), fmi3Error);
    EXPECT_NE(in.lastMessage().find("nValues = 4"), std::string::npos)
        << in.lastMessage();
    const fmi3ValueReference element = F + 1; // A.F[2] in FMI 2.0 only
    EXPECT_EQ(fmu3->api.GetFloat64(in.c, &element, 1, values, 1), fmi3Error);
    EXPECT_NE(in.lastMessage().find("not a variable of the FMI 3.0"),
              std::string::npos)
        << in.lastMessage();
    // The messages name the FMI 3.0 variable and its value reference, and
    // FMI 3.0's types
    EXPECT_EQ(fmu3->api.SetFloat64(in.c, &F, 1, values, 3), fmi3Error);
    EXPECT_NE(in.lastMessage().find("variable A.F (value reference "
                                    + std::to_string(F)
                                    + ") is an output and cannot be set"),
              std::string::npos)
        << in.lastMessage();
    EXPECT_EQ(fmu3->api.GetInt32(in.c, &F, 1, nullptr, 1), fmi3Error);
    EXPECT_NE(in.lastMessage().find("has only Float64 and Boolean variables"),
              std::string::npos)
        << in.lastMessage();
    const fmi3ValueReference p = fmu3->variable("A.p").valueReference;
    EXPECT_EQ(fmu3->api.SetFloat64(in.c, &p, 1, values, 3), fmi3Error);
    EXPECT_NE(in.lastMessage().find(
                  "parameter A.p (value reference " + std::to_string(p)
                  + ") is fixed: set it before fmi3ExitInitialization"),
              std::string::npos)
        << in.lastMessage();
    // The instance is still usable
    EXPECT_EQ(in.doStep(0.5, 0.25), fmi3OK) << in.lastMessage();
}

TEST_P(Fmi3Functions, FunctionsThatDoNotApplyLogWhy)
{
    Instance3 in(*fmu3);
    prepare(in);
    EXPECT_EQ(fmu3->api.EnterEventMode(in.c), fmi3Error);
    EXPECT_NE(in.lastMessage().find("fmi3EnterEventMode: "), std::string::npos);
    EXPECT_EQ(fmu3->api.GetDirectionalDerivative(in.c, nullptr, 0, nullptr, 0,
                                                 nullptr, 0, nullptr, 0),
              fmi3Error);
    EXPECT_NE(in.lastMessage().find("providesDirectionalDerivative"),
              std::string::npos);
    EXPECT_EQ(in.doStep(0.5, 0.25), fmi3OK) << in.lastMessage();
}

TEST_P(Fmi3Functions, GetSetStateRoundTrip)
{
    Instance3 in(*fmu3);
    prepare(in);
    const fmuTest::Fmi3Api& f = fmu3->api;
    const std::vector<double> before = outputs(in);
    fmi3FMUState saved = nullptr;
    ASSERT_EQ(f.GetFMUState(in.c, &saved), fmi3OK);
    ASSERT_EQ(in.set(arrayValues(inputs(genericB(), genericA()), *fmu3)),
              fmi3OK);
    ASSERT_EQ(in.doStep(0.5, 0.25), fmi3OK);
    const std::vector<double> after = outputs(in);
    EXPECT_NE(after, before);
    ASSERT_EQ(f.SetFMUState(in.c, saved), fmi3OK);
    EXPECT_EQ(outputs(in), before);
    // The repeated step gives the same answers
    ASSERT_EQ(in.set(arrayValues(inputs(genericB(), genericA()), *fmu3)),
              fmi3OK);
    ASSERT_EQ(in.doStep(0.5, 0.25), fmi3OK);
    EXPECT_EQ(outputs(in), after);
    EXPECT_EQ(f.FreeFMUState(in.c, &saved), fmi3OK);
    EXPECT_EQ(saved, nullptr);
}

TEST_P(Fmi3Functions, SerializedStateMovesToAnotherInstance)
{
    Instance3 in(*fmu3);
    prepare(in);
    const fmuTest::Fmi3Api& f = fmu3->api;
    fmi3FMUState saved = nullptr;
    ASSERT_EQ(f.GetFMUState(in.c, &saved), fmi3OK);
    size_t size = 0;
    ASSERT_EQ(f.SerializedFMUStateSize(in.c, saved, &size), fmi3OK);
    std::vector<fmi3Byte> bytes(size);
    ASSERT_EQ(f.SerializeFMUState(in.c, saved, bytes.data(), size), fmi3OK);
    EXPECT_EQ(std::memcmp(bytes.data(), "FOAMFMI", 7), 0);

    Instance3 other(*fmu3);
    ASSERT_NE(other.c, nullptr);
    fmi3FMUState restored = nullptr;
    ASSERT_EQ(f.DeserializeFMUState(other.c, bytes.data(), size, &restored),
              fmi3OK)
        << other.lastMessage();
    ASSERT_EQ(f.SetFMUState(other.c, restored), fmi3OK);
    EXPECT_EQ(outputs(other), outputs(in));
    EXPECT_EQ(other.doStep(0.5, 0.25), fmi3OK) << other.lastMessage();
    EXPECT_EQ(in.doStep(0.5, 0.25), fmi3OK);
    EXPECT_EQ(outputs(other), outputs(in));

    bytes[0] = 'X';
    fmi3FMUState foreign = nullptr;
    EXPECT_EQ(f.DeserializeFMUState(other.c, bytes.data(), size, &foreign),
              fmi3Error);
    EXPECT_EQ(foreign, nullptr);
}

TEST_P(Fmi3Functions, ResetReturnsToInstantiated)
{
    Instance3 in(*fmu3);
    prepare(in);
    EXPECT_EQ(fmu3->api.Reset(in.c), fmi3OK);
    EXPECT_EQ(in.doStep(0.5, 0.25), fmi3Error);
    prepare(in);
}

FMU_TEST_INSTANTIATE(Fmi3Functions);

} // namespace

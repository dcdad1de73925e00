// Every connector FMU through its C entry points: exported functions,
// instantiation checks, the state machine, value references, stepping,
// non-finite inputs and the functions a co-simulation FMU does not provide,
// and that loading and unloading the binary leaves no heap behind.
#include <malloc.h>

#include <cmath>
#include <limits>

#include "ConnectorFmuTest.hpp"
#include "ConnectorInputs.hpp"

namespace {

using namespace fmuTest;

class FmuApi : public ConnectorFmu { };

TEST_P(FmuApi, ExportsEveryFmi2Function)
{
    EXPECT_TRUE(fmu->missing.empty())
        << "first missing: " << fmu->missing.front();
    EXPECT_STREQ(fmu->api.GetVersion(), "2.0");
    EXPECT_STREQ(fmu->api.GetTypesPlatform(), "default");
}

TEST_P(FmuApi, WrongGuidIsRefused)
{
    const char* wrong = "{00000000-0000-0000-0000-000000000000}";
    Instance instance(*fmu, wrong);
    EXPECT_EQ(instance.c, nullptr);
    ASSERT_EQ(instance.log.size(), 1u);
    EXPECT_EQ(instance.log[0].status, fmi2Error);
    EXPECT_EQ(instance.log[0].category, "logStatusError");
    EXPECT_EQ(instance.log[0].message,
              "fmi2Instantiate: GUID " + std::string(wrong) + " does not match "
                  + fmu->name + "'s GUID " + fmu->guid);
}

TEST_P(FmuApi, ModelExchangeInstanceIsRefused)
{
    Instance instance(*fmu, nullptr, fmi2ModelExchange);
    EXPECT_EQ(instance.c, nullptr);
    EXPECT_EQ(instance.lastMessage(),
              "fmi2Instantiate: " + fmu->name
                  + " supports co-simulation only "
                    "(fmuType fmi2CoSimulation)");
}

TEST_P(FmuApi, CallsInTheWrongStateAreRejected)
{
    Instance in(*fmu);
    ASSERT_NE(in.c, nullptr);
    const Fmi2Api& f = fmu->api;
    EXPECT_EQ(f.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2DoStep: not allowed in state instantiated "
              "(allowed in stepComplete)");
    EXPECT_EQ(in.log.back().category, "logStatusError");
    EXPECT_EQ(f.ExitInitializationMode(in.c), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2ExitInitializationMode: not allowed in state "
              "instantiated (allowed in initializationMode)");
    std::vector<double> v;
    EXPECT_EQ(in.get({"length"}, v), fmi2Error);
    EXPECT_EQ(f.Terminate(in.c), fmi2Error);

    // A rejected call leaves the state as it was.
    ASSERT_EQ(in.initialize({}), fmi2OK);
    EXPECT_EQ(f.SetupExperiment(in.c, fmi2False, 0, 0, fmi2False, 0),
              fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2SetupExperiment: not allowed in state "
              "stepComplete (allowed in instantiated)");
    EXPECT_EQ(f.EnterInitializationMode(in.c), fmi2Error);
    EXPECT_EQ(f.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK);
    EXPECT_EQ(f.Terminate(in.c), fmi2OK);
    EXPECT_EQ(f.DoStep(in.c, 0.1, 0.1, fmi2True), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2DoStep: not allowed in state terminated "
              "(allowed in stepComplete)");
    EXPECT_EQ(in.set({{"A.r[1]", 1.0}}), fmi2Error);
    EXPECT_EQ(f.Reset(in.c), fmi2OK);
    EXPECT_EQ(in.initialize({}), fmi2OK);
}

TEST_P(FmuApi, BadValueReferencesAreNamed)
{
    Instance in(*fmu);
    ASSERT_EQ(in.initialize({}), fmi2OK);
    const Fmi2Api& f = fmu->api;
    const fmi2ValueReference bad = 100000;
    double value = 0.0;
    EXPECT_EQ(f.GetReal(in.c, &bad, 1, &value), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2GetReal: value reference 100000 is not a variable of "
                  + fmu->name + " (0 to " + std::to_string(fmu->vr.size() - 1)
                  + ")");
    const fmi2ValueReference force = fmu->ref("A.F[1]");
    // Every value reference is checked, also after an output in the list.
    const fmi2ValueReference mixed[2] = {force, bad};
    double values[2] = {0.0, 0.0};
    EXPECT_EQ(f.GetReal(in.c, mixed, 2, values), fmi2Error);
    EXPECT_NE(in.lastMessage().find("value reference 100000 is not a variable"),
              std::string::npos)
        << in.lastMessage();
    EXPECT_EQ(f.SetReal(in.c, &force, 1, &value), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2SetReal: variable A.F[1] (value reference "
                  + std::to_string(force) + ") is an output and cannot be set");
    const fmi2ValueReference p = fmu->ref("A.p[1]");
    EXPECT_EQ(f.SetReal(in.c, &p, 1, &value), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2SetReal: parameter A.p[1] (value reference "
                  + std::to_string(p)
                  + ") is fixed: set it before "
                    "fmi2ExitInitializationMode");
    fmi2Integer integer = 0;
    EXPECT_EQ(f.GetInteger(in.c, &p, 1, &integer), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2GetInteger: value reference " + std::to_string(p)
                  + " is not of type Integer: " + fmu->name
                  + " has only Real and Boolean variables");
    // The instance is still usable.
    EXPECT_EQ(f.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK);
}

TEST_P(FmuApi, UnsupportedFunctionsReturnError)
{
    Instance in(*fmu);
    ASSERT_EQ(in.initialize({}), fmi2OK);
    const Fmi2Api& f = fmu->api;
    fmi2Real x[1] = {0.0};
    fmi2Boolean b = fmi2False;
    fmi2EventInfo info {};
    const std::vector<fmi2Status> statuses
        = {f.SetTime(in.c, 1.0),
           f.EnterEventMode(in.c),
           f.NewDiscreteStates(in.c, &info),
           f.EnterContinuousTimeMode(in.c),
           f.CompletedIntegratorStep(in.c, fmi2True, &b, &b),
           f.SetContinuousStates(in.c, x, 0),
           f.GetDerivatives(in.c, x, 0),
           f.GetEventIndicators(in.c, x, 0),
           f.GetContinuousStates(in.c, x, 0),
           f.GetNominalsOfContinuousStates(in.c, x, 0)};
    for (const fmi2Status s : statuses) {
        EXPECT_EQ(s, fmi2Error);
    }
    EXPECT_EQ(in.log.size(), statuses.size());
    EXPECT_EQ(in.lastMessage(),
              "fmi2GetNominalsOfContinuousStates: model exchange is "
              "not supported: this is a co-simulation FMU");
    EXPECT_EQ(
        f.GetDirectionalDerivative(in.c, nullptr, 0, nullptr, 0, nullptr, x),
        fmi2Error);
    EXPECT_EQ(
        in.lastMessage(),
        "fmi2GetDirectionalDerivative: providesDirectionalDerivative is false");
    EXPECT_EQ(f.CancelStep(in.c), fmi2Error);
    EXPECT_EQ(f.SetRealInputDerivatives(in.c, nullptr, 0, nullptr, nullptr),
              fmi2Error);
    // None of them disturbed the instance.
    EXPECT_EQ(f.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK);
}

TEST_P(FmuApi, VariableStepSize)
{
    Instance in(*fmu);
    ASSERT_EQ(in.initialize({}), fmi2OK);
    const Fmi2Api& f = fmu->api;
    double t = 0.0;
    for (const double h : {0.1, 0.013, 1.7, 1e-4, 0.5}) {
        ASSERT_EQ(f.DoStep(in.c, t, h, fmi2False), fmi2OK) << in.lastMessage();
        t += h;
    }
    fmi2Real last = 0.0;
    EXPECT_EQ(f.GetRealStatus(in.c, fmi2LastSuccessfulTime, &last), fmi2OK);
    EXPECT_EQ(last, t); // the FMU adds the same doubles in the same order
    EXPECT_EQ(f.DoStep(in.c, 5.0, 0.1, fmi2False), fmi2Error);
    EXPECT_EQ(
        in.lastMessage().rfind("fmi2DoStep: currentCommunicationPoint = 5 does "
                               "not match the FMU time 2.3131",
                               0),
        0u)
        << in.lastMessage();
    EXPECT_EQ(f.DoStep(in.c, t, 0.0, fmi2False), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2DoStep: communicationStepSize = 0 must be finite and > 0");
}

TEST_P(FmuApi, OutputsFollowTheInputsSetBeforeGetReal)
{
    // Direct feedthrough: no doStep needed between SetReal and GetReal.
    // B.p at B's reference point (its start value is the world's anchor
    // 1 m from A.p)
    Instance in(*fmu);
    ASSERT_EQ(in.initialize({{"B.p[1]", 0.0}}), fmi2OK);
    ASSERT_EQ(in.set({{"B.r[1]", 3.0}, {"B.r[2]", 4.0}}), fmi2OK);
    EXPECT_EQ(in.get("length"), 5.0); // |(3,4,0)|, exact
    ASSERT_EQ(in.set({{"B.r[2]", 0.0}}), fmi2OK);
    ASSERT_EQ(fmu->api.DoStep(in.c, 0.0, 0.25, fmi2True), fmi2OK);
    EXPECT_EQ(in.get("length"), 3.0);
}

TEST_P(FmuApi, NonFiniteInputIsAnErrorNeverANaN)
{
    Instance in(*fmu);
    ASSERT_EQ(in.initialize(genericParameters(*fmu)), fmi2OK);
    ASSERT_EQ(in.set(inputs(genericA(), genericB())), fmi2OK);
    const Fmi2Api& f = fmu->api;
    ASSERT_EQ(f.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK);
    fmi2FMUstate saved = nullptr;
    ASSERT_EQ(f.GetFMUstate(in.c, &saved), fmi2OK);

    ASSERT_EQ(in.set({{"A.v[2]", std::numeric_limits<double>::quiet_NaN()}}),
              fmi2OK);
    EXPECT_EQ(f.DoStep(in.c, 0.1, 0.1, fmi2True), fmi2Error);
    EXPECT_EQ(in.log.back().status, fmi2Error);
    EXPECT_EQ(in.log.back().category, "logStatusError");
    EXPECT_EQ(in.lastMessage(),
              "fmi2DoStep: " + fmu->name
                  + ": input A.v[2] = nan is not finite");
    // In the error state outputs cannot be read, and nothing NaN comes out.
    std::vector<double> out(connectorOutputs().size(), 0.0);
    EXPECT_EQ(in.get(connectorOutputs(), out), fmi2Error);
    for (const double v : out) {
        EXPECT_TRUE(std::isfinite(v));
    }
    EXPECT_EQ(f.DoStep(in.c, 0.1, 0.1, fmi2True), fmi2Error);

    // Restoring a saved state recovers the instance.
    ASSERT_EQ(f.SetFMUstate(in.c, saved), fmi2OK);
    ASSERT_EQ(in.set({{"A.R[3,1]", -std::numeric_limits<double>::infinity()}}),
              fmi2OK);
    EXPECT_EQ(in.get(connectorOutputs(), out), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2GetReal: " + fmu->name
                  + ": input A.R[3,1] = -inf is not finite");
    ASSERT_EQ(f.SetFMUstate(in.c, saved), fmi2OK);
    EXPECT_EQ(f.DoStep(in.c, 0.1, 0.1, fmi2True), fmi2OK);
    EXPECT_EQ(in.get(connectorOutputs(), out), fmi2OK);
    EXPECT_EQ(f.FreeFMUstate(in.c, &saved), fmi2OK);
}

TEST_P(FmuApi, DebugLoggingCategories)
{
    Instance in(*fmu);
    const Fmi2Api& f = fmu->api;
    const fmi2String unknown[] = {"logEverything"};
    EXPECT_EQ(f.SetDebugLogging(in.c, fmi2True, 1, unknown), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2SetDebugLogging: unknown log category "
              "\"logEverything\" (known: logStatusError, logCalls, "
              "refusedParameter)");
    const fmi2String calls[] = {"logCalls"};
    EXPECT_EQ(f.SetDebugLogging(in.c, fmi2True, 1, calls), fmi2OK);
    EXPECT_EQ(f.SetupExperiment(in.c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
    EXPECT_EQ(in.log.back().category, "logCalls");
    EXPECT_EQ(in.lastMessage(), "fmi2SetupExperiment");
}

TEST_P(FmuApi, RefusedParameterIsLoggedWithItsNameAndCode)
{
    // Every connector declares A.p: A.p[2] = NaN is refused at
    // fmi2ExitInitializationMode. With the category refusedParameter on, the
    // refusal comes first in it as "<name> <code>: <message>", then the
    // error in logStatusError, whose text is the same as without it.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Fmi2Api& f = fmu->api;
    const std::string message = fmu->name
        + ": parameter A.p[2] = nan m is out of range (allowed: finite)";

    Instance quiet(*fmu);
    EXPECT_EQ(quiet.initialize({{"A.p[2]", nan}}), fmi2Error);
    ASSERT_EQ(quiet.log.size(), 1u);
    EXPECT_EQ(quiet.log[0].category, "logStatusError");
    EXPECT_EQ(quiet.log[0].message, "fmi2ExitInitializationMode: " + message);

    for (const bool all : {true, false}) {
        Instance in(*fmu);
        const fmi2String categories[] = {"refusedParameter"};
        ASSERT_EQ(f.SetDebugLogging(in.c, fmi2True, all ? 0 : 1, categories),
                  fmi2OK);
        EXPECT_EQ(in.initialize({{"A.p[2]", nan}}), fmi2Error);
        std::vector<LogRecord> log; // without logCalls (on with all)
        for (const LogRecord& r : in.log) {
            if (r.category != "logCalls") {
                log.push_back(r);
            }
        }
        ASSERT_EQ(log.size(), 2u);
        EXPECT_EQ(log[0].status, fmi2Error);
        EXPECT_EQ(log[0].category, "refusedParameter");
        EXPECT_EQ(log[0].message, "A.p[2] notFinite: " + message);
        EXPECT_EQ(log[1].category, "logStatusError");
        EXPECT_EQ(log[1].message, quiet.log[0].message);
    }

    // Debug logging off again: the error alone
    Instance off(*fmu);
    ASSERT_EQ(f.SetDebugLogging(off.c, fmi2True, 0, nullptr), fmi2OK);
    ASSERT_EQ(f.SetDebugLogging(off.c, fmi2False, 0, nullptr), fmi2OK);
    EXPECT_EQ(off.initialize({{"A.p[2]", nan}}), fmi2Error);
    for (const LogRecord& r : off.log) {
        EXPECT_NE(r.category, "refusedParameter") << r.message;
    }
    EXPECT_EQ(off.lastMessage(), quiet.log[0].message);
}

TEST_P(FmuApi, ParametersSetAgainBeforeInitializationAreChecked)
{
    // Outputs read before initialization build the law for the parameters
    // then; a parameter set after that is checked for itself
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Instance in(*fmu);
    const Fmi2Api& f = fmu->api;
    ASSERT_EQ(f.SetupExperiment(in.c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
    ASSERT_EQ(f.EnterInitializationMode(in.c), fmi2OK);
    std::vector<double> out;
    ASSERT_EQ(in.get(connectorOutputs(), out), fmi2OK);
    ASSERT_EQ(in.set({{"A.p[1]", nan}}), fmi2OK);
    EXPECT_EQ(in.get(connectorOutputs(), out), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2GetReal: " + fmu->name
                  + ": parameter A.p[1] = nan m is out of range (allowed: "
                    "finite)");
}

TEST_P(FmuApi, RestConfigurationHasNoLoad)
{
    // inputsStartAtRest = true promises zero loads at the start values.
    Instance in(*fmu);
    const Fmi2Api& f = fmu->api;
    if (fmu->vr.count("inputsStartAtRest") == 0) {
        GTEST_SKIP() << fmu->name << " declares no rest configuration";
    }
    ASSERT_EQ(in.initialize({}), fmi2OK);
    const fmi2ValueReference rest = fmu->ref("inputsStartAtRest");
    fmi2Boolean value = fmi2False;
    ASSERT_EQ(f.GetBoolean(in.c, &rest, 1, &value), fmi2OK);
    EXPECT_EQ(value, fmi2True);
    ASSERT_EQ(f.DoStep(in.c, 0.0, 0.1, fmi2True), fmi2OK);
    std::vector<double> out;
    ASSERT_EQ(in.get(connectorOutputs(), out), fmi2OK);
    for (std::size_t i = 0; i < 12; ++i) { // A.F, A.M, B.F, B.M
        // Tolerance: round-off of O(1) m geometry times stiffnesses up to
        // ~1e3 N/m (linearSpring and linearDamper give exactly 0).
        EXPECT_NEAR(out[i], 0.0, 1e-10) << connectorOutputs()[i];
    }
    EXPECT_EQ(f.SetBoolean(in.c, &rest, 1, &value), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2SetBoolean: variable inputsStartAtRest is "
              "a constant and cannot be set");
    double real = 0.0;
    EXPECT_EQ(f.GetReal(in.c, &rest, 1, &real), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2GetReal: value reference " + std::to_string(rest)
                  + " (inputsStartAtRest) is not of type Real");
}

// Each load of an FMU binary starts its own copy of libstdc++, which takes
// a 72704-byte emergency pool for exceptions; the binary frees it when
// unloaded (fmu/cmake/staticRuntimeUnload.cpp). Ten loads and unloads, each
// from its own unpacked copy so that every dlopen really loads, may leave
// less than one such pool on the heap. Under AddressSanitizer glibc's
// mallinfo2 does not see the heap: LeakSanitizer checks this there.
TEST_P(FmuApi, UnloadingLeavesNoHeapBehind)
{
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "LeakSanitizer checks the heap of a sanitized build";
#endif
    {
        LoadedFmu warmUp(GetParam());
    }
    const std::size_t before = mallinfo2().uordblks;
    for (int load = 0; load < 10; ++load) {
        LoadedFmu again(GetParam());
        ASSERT_TRUE(again.missing.empty());
    }
    const std::size_t after = mallinfo2().uordblks;
    EXPECT_LT(after, before + 72704)
        << after - before
        << " bytes left on the heap by 10 loads and unloads of " << GetParam();
}

FMU_TEST_INSTANTIATE(FmuApi);

} // namespace

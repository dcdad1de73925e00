// FMU states of every connector FMU: get/set round trip, serialization round
// trip (also into another instance), and rejection of foreign or damaged
// bytes.
#include <cstring>
#include <random>

#include "ConnectorFmuTest.hpp"
#include "ConnectorInputs.hpp"

namespace {

using namespace fmuTest;

//- Initialised instance with generic parameters and inputs, stepped once
void prepare(const LoadedFmu& fmu, Instance& in)
{
    ASSERT_NE(in.c, nullptr);
    ASSERT_EQ(in.initialize(genericParameters(fmu)), fmi2OK);
    ASSERT_EQ(in.set(inputs(genericA(), genericB())), fmi2OK);
    ASSERT_EQ(fmu.api.DoStep(in.c, 0.0, 0.5, fmi2True), fmi2OK);
}

std::vector<double> outputs(Instance& in)
{
    std::vector<double> v;
    EXPECT_EQ(in.get(connectorOutputs(), v), fmi2OK) << in.lastMessage();
    return v;
}

class FmuStates : public ConnectorFmu {
protected:
    //- `in` prepared (prepare), its outputs then in `before` and its FMU
    //  state then in `saved`
    void prepareAndSave(Instance& in)
    {
        prepare(*fmu, in);
        before = outputs(in);
        ASSERT_EQ(fmu->api.GetFMUstate(in.c, &saved), fmi2OK);
    }

    std::vector<double> before;
    fmi2FMUstate saved = nullptr;
};

std::vector<fmi2Byte> serialize(const LoadedFmu& fmu, Instance& in,
                                fmi2FMUstate s)
{
    size_t size = 0;
    EXPECT_EQ(fmu.api.SerializedFMUstateSize(in.c, s, &size), fmi2OK);
    std::vector<fmi2Byte> bytes(size);
    EXPECT_EQ(fmu.api.SerializeFMUstate(in.c, s, bytes.data(), size), fmi2OK);
    return bytes;
}

TEST_P(FmuStates, GetSetStateRoundTrip)
{
    Instance in(*fmu);
    ASSERT_NO_FATAL_FAILURE(prepareAndSave(in));
    const Fmi2Api& f = fmu->api;

    ASSERT_EQ(in.set(inputs(genericB(), genericA())), fmi2OK);
    ASSERT_EQ(f.DoStep(in.c, 0.5, 0.25, fmi2False), fmi2OK);
    EXPECT_NE(outputs(in), before);

    ASSERT_EQ(f.SetFMUstate(in.c, saved), fmi2OK);
    EXPECT_EQ(outputs(in), before); // bit for bit: the same values come back
    fmi2Real time = 0.0;
    EXPECT_EQ(f.GetRealStatus(in.c, fmi2LastSuccessfulTime, &time), fmi2OK);
    EXPECT_EQ(time, 0.5);
    // The repeated step starts again at 0.5 (PIMPLE outer correctors).
    EXPECT_EQ(f.DoStep(in.c, 0.5, 0.25, fmi2False), fmi2OK);

    // Saving into an existing state reuses it.
    fmi2FMUstate reused = saved;
    ASSERT_EQ(f.GetFMUstate(in.c, &reused), fmi2OK);
    EXPECT_EQ(reused, saved);
    ASSERT_EQ(f.FreeFMUstate(in.c, &saved), fmi2OK);
    EXPECT_EQ(saved, nullptr);
    EXPECT_EQ(f.SetFMUstate(in.c, reused), fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2SetFMUstate: FMU state handle was not created by "
              "this instance or was already freed");
}

TEST_P(FmuStates, SerializeRoundTripIntoAnotherInstance)
{
    Instance in(*fmu);
    ASSERT_NO_FATAL_FAILURE(prepareAndSave(in));
    const Fmi2Api& f = fmu->api;
    const std::vector<fmi2Byte> bytes = serialize(*fmu, in, saved);

    Instance other(*fmu); // fresh, in state instantiated
    fmi2FMUstate restored = nullptr;
    ASSERT_EQ(
        f.DeSerializeFMUstate(other.c, bytes.data(), bytes.size(), &restored),
        fmi2OK)
        << other.lastMessage();
    ASSERT_EQ(f.SetFMUstate(other.c, restored), fmi2OK);
    EXPECT_EQ(outputs(other), before);
    EXPECT_EQ(f.DoStep(other.c, 0.5, 0.1, fmi2False), fmi2OK)
        << other.lastMessage();
    EXPECT_EQ(serialize(*fmu, other, restored), bytes);

    std::vector<fmi2Byte> small(bytes.size() - 1);
    EXPECT_EQ(f.SerializeFMUstate(in.c, saved, small.data(), small.size()),
              fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2SerializeFMUstate: buffer of " + std::to_string(small.size())
                  + " bytes is too small, " + std::to_string(bytes.size())
                  + " bytes needed (fmi2SerializedFMUstateSize)");
}

TEST_P(FmuStates, DeserializingGarbageFails)
{
    Instance in(*fmu);
    prepare(*fmu, in);
    const Fmi2Api& f = fmu->api;
    fmi2FMUstate saved = nullptr;
    ASSERT_EQ(f.GetFMUstate(in.c, &saved), fmi2OK);
    const std::vector<fmi2Byte> good = serialize(*fmu, in, saved);

    std::mt19937 rng(99);
    std::vector<fmi2Byte> garbage(good.size());
    for (fmi2Byte& b : garbage) {
        b = fmi2Byte(rng());
    }
    fmi2FMUstate s = nullptr;
    EXPECT_EQ(f.DeSerializeFMUstate(in.c, garbage.data(), garbage.size(), &s),
              fmi2Error);
    EXPECT_EQ(s, nullptr);
    EXPECT_EQ(in.lastMessage(),
              "fmi2DeSerializeFMUstate: bytes are not a serialized "
              "state of this FMU (magic \"FOAMFMI\" not found)");

    EXPECT_EQ(f.DeSerializeFMUstate(in.c, good.data(), 10, &s), fmi2Error);
    EXPECT_NE(in.lastMessage().find(
                  "serialized state of 10 bytes is shorter than its header"),
              std::string::npos)
        << in.lastMessage();

    std::vector<fmi2Byte> versioned = good;
    versioned[8] = 99; // first byte of the format version
    EXPECT_EQ(
        f.DeSerializeFMUstate(in.c, versioned.data(), versioned.size(), &s),
        fmi2Error);
    EXPECT_EQ(in.lastMessage(),
              "fmi2DeSerializeFMUstate: serialized state has format "
              "version 99, expected 1");

    std::vector<fmi2Byte> longer = good;
    longer.push_back(0);
    EXPECT_EQ(f.DeSerializeFMUstate(in.c, longer.data(), longer.size(), &s),
              fmi2Error);
    // the size of this FMU's states first (then, for an FMU without
    // internal state, the size a state with one would need)
    EXPECT_EQ(in.lastMessage().rfind(
                  "fmi2DeSerializeFMUstate: serialized state has "
                      + std::to_string(longer.size()) + " bytes, expected "
                      + std::to_string(good.size()),
                  0),
              0u)
        << in.lastMessage();
    EXPECT_EQ(s, nullptr);
    // The instance is untouched by the rejected calls.
    EXPECT_EQ(f.DoStep(in.c, 0.5, 0.1, fmi2False), fmi2OK);
}

FMU_TEST_INSTANTIATE(FmuStates);

TEST(FmuState, StateOfAnotherFmuIsRejected)
{
    LoadedFmu spring("linearSpring");
    LoadedFmu damper("linearDamper");
    Instance s(spring);
    prepare(spring, s);
    fmi2FMUstate saved = nullptr;
    ASSERT_EQ(spring.api.GetFMUstate(s.c, &saved), fmi2OK);
    const std::vector<fmi2Byte> bytes = serialize(spring, s, saved);
    Instance d(damper);
    fmi2FMUstate foreign = nullptr;
    EXPECT_EQ(damper.api.DeSerializeFMUstate(d.c, bytes.data(), bytes.size(),
                                             &foreign),
              fmi2Error);
    EXPECT_EQ(d.lastMessage(),
              "fmi2DeSerializeFMUstate: serialized state belongs to the "
              "FMU with GUID "
                  + spring.guid + ", not " + damper.guid);
    // A handle of another instance is not accepted either.
    EXPECT_EQ(damper.api.SetFMUstate(d.c, saved), fmi2Error);
}

} // namespace

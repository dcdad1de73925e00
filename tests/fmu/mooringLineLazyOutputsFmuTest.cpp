// mooringLine.fmu's outputs computed when read: a caller that reads only
// the loads, repeats steps (fmi2GetFMUstate, fmi2SetFMUstate) and now and
// then reads every output gets, to the bit, what a caller that reads
// every output after every step gets, in still water and in a changing
// flow (whose acceleration acts on the line); energyAccount = 0 changes
// no output but the energy account's, which stay 0.
#include <gtest/gtest.h>

#include <cmath>

#include "mooringLineFmuSupport.hpp"

namespace {

using namespace fmuTest;
using namespace mooringLineFmuTest;

//- The names of every output and local variable, in value-reference order
std::vector<std::string> computedNames(const LoadedFmu& fmu)
{
    std::vector<std::string> names;
    const pugi::xml_node variables
        = fmu.description.child("fmiModelDescription").child("ModelVariables");
    for (pugi::xml_node v : variables.children("ScalarVariable")) {
        const std::string causality = v.attribute("causality").value();
        if (causality == "output" || causality == "local") {
            names.push_back(v.attribute("name").value());
        }
    }
    return names;
}

const std::vector<std::string> loadNames
    = {"A.F[1]", "A.F[2]", "A.F[3]", "A.M[1]", "A.M[2]", "A.M[3]",
       "B.F[1]", "B.F[2]", "B.F[3]", "B.M[1]", "B.M[2]", "B.M[3]"};

//- The floater's inputs at t and, with `flow`, a water velocity at the
//  shape points that changes from step to step
std::map<std::string, double> inputsAt(double t, bool flow)
{
    std::map<std::string, double> m = inputs(floater(t), BodyKinematics());
    for (int k = 1; flow && k <= 11; ++k) {
        m["shape.Ux[" + std::to_string(k) + "]"]
            = 0.3 * std::sin(2.0 * t) * k / 11.0;
        m["shape.Uz[" + std::to_string(k) + "]"] = 0.1 * std::cos(t);
    }
    return m;
}

TEST(MooringLineLazyOutputsFmu, ReadLaterTheyAreThoseOfEveryStep)
{
    for (const bool flow : {false, true}) {
        LoadedFmu fmu("mooringLine");
        Instance every(fmu), lazy(fmu);
        ASSERT_EQ(initialise(fmu, every), fmi2OK) << every.lastMessage();
        ASSERT_EQ(initialise(fmu, lazy), fmi2OK) << lazy.lastMessage();
        const std::vector<std::string> names = computedNames(fmu);
        const double h = 0.1;
        fmi2FMUstate saved = nullptr;
        for (int k = 0; k < 24; ++k) {
            const double t = k * h;
            if (k % 3 == 1) {
                // an outer corrector: a step with other inputs, undone
                ASSERT_EQ(fmu.api.GetFMUstate(lazy.c, &saved), fmi2OK);
                ASSERT_EQ(lazy.set(inputsAt(t + h + 0.05, flow)), fmi2OK);
                ASSERT_EQ(fmu.api.DoStep(lazy.c, t, h, fmi2False), fmi2OK)
                    << lazy.lastMessage();
                std::vector<double> loads;
                ASSERT_EQ(lazy.get(loadNames, loads), fmi2OK);
                ASSERT_EQ(fmu.api.SetFMUstate(lazy.c, saved), fmi2OK);
            }
            for (Instance* in : {&every, &lazy}) {
                ASSERT_EQ(in->set(inputsAt(t + h, flow)), fmi2OK);
                ASSERT_EQ(fmu.api.DoStep(in->c, t, h, fmi2False), fmi2OK)
                    << in->lastMessage();
            }
            std::vector<double> all, loads;
            ASSERT_EQ(every.get(names, all), fmi2OK);
            ASSERT_EQ(lazy.get(loadNames, loads), fmi2OK);
            EXPECT_EQ(loads, std::vector<double>(all.begin(), all.begin() + 12))
                << flow << " " << k;
            if (k % 5 == 4) {
                std::vector<double> later;
                ASSERT_EQ(lazy.get(names, later), fmi2OK);
                for (std::size_t i = 0; i < names.size(); ++i) {
                    EXPECT_EQ(later[i], all[i])
                        << flow << " " << k << " " << names[i];
                }
            }
        }
        fmu.api.FreeFMUstate(lazy.c, &saved);
    }
}

TEST(MooringLineLazyOutputsFmu, WithoutTheEnergyAccountOnlyItsOutputsChange)
{
    LoadedFmu fmu("mooringLine");
    Instance on(fmu), off(fmu);
    ASSERT_EQ(initialise(fmu, on, {{"energyAccount", 1.0}}), fmi2OK)
        << on.lastMessage();
    ASSERT_EQ(initialise(fmu, off, {{"energyAccount", 0.0}}), fmi2OK)
        << off.lastMessage();
    const std::vector<std::string> names = computedNames(fmu);
    const double h = 0.1;
    for (int k = 0; k < 20; ++k) {
        const double t = k * h;
        std::vector<double> a, b;
        for (Instance* in : {&on, &off}) {
            ASSERT_EQ(in->set(inputsAt(t + h, true)), fmi2OK);
            ASSERT_EQ(fmu.api.DoStep(in->c, t, h, fmi2False), fmi2OK)
                << in->lastMessage();
        }
        ASSERT_EQ(on.get(names, a), fmi2OK);
        ASSERT_EQ(off.get(names, b), fmi2OK);
        for (std::size_t i = 0; i < names.size(); ++i) {
            const std::string& n = names[i];
            const bool account = (n.find("Work") != std::string::npos
                                  || n.find("issipated") != std::string::npos)
                && n != "dissipatedPower";
            if (account) {
                EXPECT_EQ(b[i], 0.0) << k << " " << n;
            } else {
                EXPECT_EQ(b[i], a[i]) << k << " " << n;
            }
        }
    }
    EXPECT_GT(std::abs(on.get("fairleadWork")), 0.0);
    LoadedFmu loaded("mooringLine");
    expectInitializationRefused(
        loaded, changed(chainParameters, {{"energyAccount", 0.5}}),
        "fmi2ExitInitializationMode: mooringLine: parameter energyAccount = "
        "0.5 is out of range (allowed: 0 or 1)");
}

} // namespace

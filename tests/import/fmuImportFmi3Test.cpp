// FMI 3.0 FMUs through the importer: the description (arrays shown as
// elements with the 2.0 names), the connector interface's terms as arrays,
// instances driven through fmi3 beside the 2.0 FMU of the same connector,
// and the refusals: model exchange or scheduled execution only, clocks,
// arrays of the wrong dimensions, a missing terminal variable. The
// refused FMUs are the linear spring's 3.0 FMU with its
// modelDescription.xml edited.
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>
#include <zip.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using fmuImport::connector::Problem;
using fmuImport::connector::Variables;

const std::string spring3 = FMI3_FMU_DIR "/linearSpring.fmu";
const std::string spring2 = FMI3_FMU_DIR "/../linearSpring.fmu";

std::string entry(const std::string& archive, const std::string& name)
{
    int code = 0;
    zip_t* z = zip_open(archive.c_str(), ZIP_RDONLY, &code);
    zip_stat_t st;
    zip_file_t* f = z && zip_stat(z, name.c_str(), 0, &st) == 0
        ? zip_fopen(z, name.c_str(), 0)
        : nullptr;
    if (!f)
        throw std::runtime_error("cannot read " + name + " of " + archive);
    std::string text(st.size, '\0');
    zip_fread(f, &text[0], st.size);
    zip_fclose(f);
    zip_close(z);
    return text;
}

// The 3.0 spring with its description's text from replaced by to
std::string edited(const std::string& name, const std::string& from,
                   const std::string& to)
{
    std::string xml = entry(spring3, "modelDescription.xml");
    const std::size_t at = xml.find(from);
    if (at == std::string::npos)
        throw std::runtime_error("no '" + from + "' in the description");
    xml.replace(at, from.size(), to);
    const std::string target
        = (std::filesystem::temp_directory_path() / (name + ".fmu")).string();
    std::filesystem::copy_file(
        spring3, target, std::filesystem::copy_options::overwrite_existing);
    int code = 0;
    zip_t* z = zip_open(target.c_str(), 0, &code);
    zip_source_t* data = zip_source_buffer(z, xml.data(), xml.size(), 0);
    if (zip_file_add(z, "modelDescription.xml", data, ZIP_FL_OVERWRITE) < 0
        || zip_close(z) != 0)
        throw std::runtime_error("cannot write " + target);
    return target;
}

std::string loadError(const std::string& path)
{
    try {
        const fmuImport::Fmu fmu(path);
    } catch (const fmuImport::Error& e) {
        return e.what();
    }
    return "no error";
}

std::string problemsText(const fmuImport::Fmu& fmu)
{
    std::string text;
    const Variables variables(fmu);
    for (const Problem& p : variables.problems())
        text += p.text + "\n";
    return text;
}

TEST(Fmi3Import, DescriptionShowsArraysAsElements)
{
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu3(spring3), fmu2(spring2);
    const fmuImport::ModelDescription& md = fmu3.modelDescription();
    EXPECT_EQ(md.fmiVersion, "3.0");
    EXPECT_EQ(md.fmiMajorVersion, 3);
    EXPECT_EQ(md.guid, fmu2.modelDescription().guid); // instantiationToken
    EXPECT_TRUE(md.canGetAndSetFMUstate);
    EXPECT_TRUE(md.canSerializeFMUstate);
    EXPECT_FALSE(md.hasEventMode);

    const fmuImport::Variable& r = fmu3.variable("A.R[2,3]");
    EXPECT_EQ(r.typeName, "Float64");
    EXPECT_EQ(r.arrayName, "A.R");
    EXPECT_EQ(r.dimensions, std::vector<std::size_t>({3, 3}));
    EXPECT_EQ(r.element, 5u); // row-major
    EXPECT_EQ(r.startString, "0");
    EXPECT_EQ(fmu3.variable("A.R[1,1]").start, 1.0);
    // Every 2.0 variable is there, with its value reference, type,
    // causality, variability and unit
    for (const fmuImport::Variable& v : fmu2.modelDescription().variables) {
        ASSERT_TRUE(fmu3.hasVariable(v.name)) << v.name;
        const fmuImport::Variable& w = fmu3.variable(v.name);
        EXPECT_EQ(w.valueReference, v.valueReference) << v.name;
        EXPECT_EQ(w.type, v.type) << v.name;
        EXPECT_EQ(w.causality, v.causality) << v.name;
        EXPECT_EQ(w.variability, v.variability) << v.name;
        EXPECT_EQ(w.unit, v.unit) << v.name;
    }
    EXPECT_EQ(fmu3.modelDescription().variables.size(),
              fmu2.modelDescription().variables.size());
}

TEST(Fmi3Import, ConnectorTermsAreArrays)
{
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu3(spring3), fmu2(spring2);
    const Variables v3(fmu3), v2(fmu2);
    EXPECT_TRUE(v3.problems().empty()) << problemsText(fmu3);
    EXPECT_TRUE(v3.twoBody());
    for (const auto& term : fmuImport::connector::vocabulary())
        EXPECT_EQ(v3.refs(term.base), v2.refs(term.base)) << term.base;
}

// The same inputs and steps through fmi2 and fmi3: the same bits
TEST(Fmi3Import, StepsGiveTheBitsOfTheFmi2Fmu)
{
    fixtures::PrivateTmpDir tmp;
    for (const fmuImport::Isolation isolation :
         {fmuImport::Isolation::none, fmuImport::Isolation::process}) {
        const fmuImport::Fmu fmu3(spring3, {isolation, 0, ""}),
            fmu2(spring2, {isolation, 0, ""});
        fmuImport::Instance i3(fmu3, "s3"), i2(fmu2, "s2");
        const Variables v(fmu3);
        std::vector<unsigned int> in, out;
        for (const char* t : {"A.r", "A.R", "A.v", "B.r", "B.v", "B.omega"})
            in.insert(in.end(), v.refs(t).begin(), v.refs(t).end());
        for (const char* t : {"A.F", "A.M", "B.F", "B.M", "tension"})
            out.insert(out.end(), v.refs(t).begin(), v.refs(t).end());
        for (fmuImport::Instance* i : {&i3, &i2}) {
            i->setupExperiment(0, true, 1);
            // one element of an array before initialization, the others
            // keep their start values
            i->setReal({fmu3.variable("B.p[2]").valueReference}, {0.25});
            i->setReal({fmu3.variable("stiffness").valueReference}, {70.0});
            i->enterInitializationMode();
            i->exitInitializationMode();
        }
        fmuImport::Instance::State saved3 = i3.getState(),
                                   saved2 = i2.getState();
        auto step = [&](int k) {
            std::vector<double> x(in.size());
            for (std::size_t j = 0; j < x.size(); ++j)
                x[j] = 0.1 * std::sin(0.3 * k + j) + (j == 15 ? 1.2 : 0);
            i3.setReal(in, x);
            i2.setReal(in, x);
            i3.doStep(i3.time(), 0.01);
            i2.doStep(i2.time(), 0.01);
            const std::vector<double> y3 = i3.getReal(out),
                                      y2 = i2.getReal(out);
            ASSERT_EQ(y3.size(), y2.size());
            for (std::size_t j = 0; j < y3.size(); ++j)
                ASSERT_EQ(std::memcmp(&y3[j], &y2[j], sizeof(double)), 0)
                    << "step " << k << ", output " << j;
        };
        for (int k = 0; k < 20; ++k)
            step(k);
        // back to the start: the same again
        i3.setState(saved3);
        i2.setState(saved2);
        EXPECT_EQ(i3.time(), 0.0);
        for (int k = 0; k < 5; ++k)
            step(k);
        const std::vector<char> bytes3 = i3.serializeState(saved3),
                                bytes2 = i2.serializeState(saved2);
        EXPECT_EQ(bytes3, bytes2); // the export's promise, kept through import
        fmuImport::Instance::State back = i3.deserializeState(bytes3);
        i3.setState(back);
        i3.terminate();
    }
}

TEST(Fmi3Import, ElementsOfOneArrayInAnyOrder)
{
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu(spring3);
    fmuImport::Instance i(fmu, "s");
    i.setupExperiment(0);
    i.enterInitializationMode();
    const unsigned int r3 = fmu.variable("B.r[3]").valueReference,
                       r1 = fmu.variable("B.r[1]").valueReference;
    i.setReal({r3, r1}, {3.0, 2.0}); // part of B.r, backwards
    EXPECT_EQ(i.getReal({r1, r3, fmu.variable("B.r[2]").valueReference}),
              std::vector<double>({2.0, 3.0, 0.0}));
    EXPECT_THROW(i.getReal({999999}), fmuImport::Error);
    i.exitInitializationMode();
}

// After fmi3Reset the instance is instantiated again: a part of an array
// set before initialization takes the others from the start values, not
// from the sets before the reset
TEST(Fmi3Import, ResetStartsOver)
{
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu(spring3);
    const unsigned int r1 = fmu.variable("B.r[1]").valueReference,
                       r2 = fmu.variable("B.r[2]").valueReference,
                       force = fmu.variable("A.F[1]").valueReference;
    auto run = [&](fmuImport::Instance& i, bool before) {
        i.setupExperiment(0);
        if (before)
            i.setReal({r2}, {0.5});
        i.setReal({r1}, {2.0});
        i.enterInitializationMode();
        i.exitInitializationMode();
        i.doStep(0, 0.01);
        return i.getReal({force, r2});
    };
    fmuImport::Instance used(fmu, "used"), fresh(fmu, "fresh");
    run(used, true);
    used.reset();
    const std::vector<double> again = run(used, false),
                              first = run(fresh, false);
    EXPECT_EQ(again, first);
    EXPECT_EQ(first[1], 0.0); // B.r[2]'s start value
}

TEST(Fmi3Import, ModelExchangeOrScheduledExecutionOnlyIsRefused)
{
    fixtures::PrivateTmpDir tmp;
    const std::string cs = "<CoSimulation modelIdentifier=\"linearSpring\"";
    EXPECT_NE(
        loadError(edited("me3", cs,
                         "<ModelExchange modelIdentifier=\"linearSpring\""))
            .find("has no <CoSimulation> element: model exchange only, "
                  "and the importer runs co-simulation FMUs only"),
        std::string::npos);
    EXPECT_NE(
        loadError(
            edited("se3", cs,
                   "<ScheduledExecution modelIdentifier=\"linearSpring\""))
            .find("scheduled execution only"),
        std::string::npos);
}

TEST(Fmi3Import, ClocksAreRefused)
{
    fixtures::PrivateTmpDir tmp;
    const std::string vars = "<ModelVariables>";
    EXPECT_NE(
        loadError(
            edited(
                "clock3", vars,
                vars
                    + "<Clock name=\"tick\" valueReference=\"900\" "
                      "causality=\"input\" intervalVariability=\"triggered\"/>"))
            .find("variable 'tick' is a Clock: the importer cannot drive "
                  "clocks"),
        std::string::npos);
    EXPECT_NE(
        loadError(
            edited(
                "clocked3", vars,
                vars
                    + "<Float64 name=\"x\" valueReference=\"901\" "
                      "causality=\"output\" variability=\"discrete\" clocks=\"900\"/>"))
            .find("variable 'x' is clocked (clocks=\"900\")"),
        std::string::npos);
}

TEST(Fmi3Import, WrongDimensionsAreNamed)
{
    fixtures::PrivateTmpDir tmp;
    // A.r with 4 elements
    const std::string r
        = "causality=\"input\" variability=\"continuous\" "
          "unit=\"m\" start=\"0 0 0\">\n      <Dimension start=\"3\"/>";
    const fmuImport::Fmu four(edited(
        "dims4", r,
        "causality=\"input\" variability=\"continuous\" unit=\"m\" start=\"0 0 0 "
        "0\">\n      <Dimension start=\"4\"/>"));
    EXPECT_NE(problemsText(four).find("A.r is an array of dimensions [4], "
                                      "expected an array of dimensions [3]"),
              std::string::npos)
        << problemsText(four);
    EXPECT_TRUE(Variables(four).refs("A.r").empty());

    // A.R as 9 values in a row
    const std::string R = "start=\"1 0 0 0 1 0 0 0 1\">\n      <Dimension "
                          "start=\"3\"/>\n      <Dimension start=\"3\"/>";
    const fmuImport::Fmu flat(
        edited("dims9", R,
               "start=\"1 0 0 0 1 0 0 0 1\">\n      <Dimension start=\"9\"/>"));
    EXPECT_NE(problemsText(flat).find(
                  "A.R is an array of dimensions [9], expected an array of "
                  "dimensions [3, 3] (row-major)"),
              std::string::npos)
        << problemsText(flat);

    // start values that do not fill the array
    EXPECT_NE(loadError(edited("starts3", "start=\"1 0 0 0 1 0 0 0 1\"",
                               "start=\"1 0 0 0 1 0\""))
                  .find("variable 'A.R' has 6 start values, expected 9"),
              std::string::npos);
}

TEST(Fmi3Import, MissingTerminalVariableIsNamed)
{
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu(
        edited("noAF", "<Float64 name=\"A.F\"", "<Float64 name=\"A.Fx\""));
    const Variables v(fmu);
    EXPECT_EQ(v.missingRequired(), std::vector<std::string>({"A.F"}));
    EXPECT_NE(problemsText(fmu).find(
                  "missing A.F: expected an output Float64 A.F, an array of "
                  "dimensions [3]"),
              std::string::npos)
        << problemsText(fmu);
}

} // namespace

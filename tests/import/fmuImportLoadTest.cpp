// Loading FMUs: the description of the first-order lag fixture, and one
// broken archive per failure the importer must name.
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace {

using fixtures::fmuPath;

// Loads path expecting Error; the message must name the file and contain
// every fragment; no unpacked files may stay behind.
void expectLoadError(const std::string& path,
                     const std::vector<std::string>& fragments)
{
    fixtures::PrivateTmpDir tmp;
    try {
        fmuImport::Fmu fmu(path);
        ADD_FAILURE() << "loading " << path << " did not throw";
    } catch (const fmuImport::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("'" + path + "'"), std::string::npos) << message;
        for (const std::string& fragment : fragments)
            EXPECT_NE(message.find(fragment), std::string::npos)
                << "missing '" << fragment << "' in: " << message;
    }
    EXPECT_TRUE(tmp.contents().empty()) << "the importer left files in TMPDIR";
}

TEST(FmuLoad, ReadsTheModelDescription)
{
    const fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
    const fmuImport::ModelDescription& md = fmu.modelDescription();
    EXPECT_EQ(md.fmiVersion, "2.0");
    EXPECT_EQ(md.modelName, "firstOrderLag");
    EXPECT_EQ(md.modelIdentifier, "firstOrderLag");
    EXPECT_EQ(md.guid, "{6f1c2a7e-4b1d-4c55-9a0e-lag000000001}");
    EXPECT_EQ(md.generationTool, "foamFmiConnectors test fixtures");
    EXPECT_TRUE(md.canHandleVariableCommunicationStepSize);
    EXPECT_TRUE(md.canGetAndSetFMUstate);
    EXPECT_TRUE(md.canSerializeFMUstate);
    EXPECT_FALSE(md.providesDirectionalDerivative);
    ASSERT_TRUE(md.hasDefaultExperiment);
    EXPECT_EQ(md.startTime, 0.0);
    EXPECT_EQ(md.stopTime, 3.0);
    EXPECT_EQ(md.stepSize, 0.01);
    ASSERT_EQ(md.variables.size(), 7u);
    EXPECT_EQ(md.variables[2].name, "u");
}

TEST(FmuLoad, LooksUpVariablesByName)
{
    const fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
    const fmuImport::Variable& T = fmu.variable("timeConstant");
    EXPECT_EQ(T.valueReference, 0u);
    EXPECT_EQ(T.type, fmuImport::Type::Real);
    EXPECT_EQ(T.causality, fmuImport::Causality::parameter);
    EXPECT_EQ(T.variability, fmuImport::Variability::fixed);
    EXPECT_EQ(T.unit, "s");
    EXPECT_EQ(T.description, "time constant T");
    EXPECT_TRUE(T.hasStart);
    EXPECT_EQ(T.start, 1.0);

    const fmuImport::Variable& y = fmu.variable("y");
    EXPECT_EQ(y.causality, fmuImport::Causality::output);
    EXPECT_FALSE(y.hasStart);

    const fmuImport::Variable& hold = fmu.variable("hold");
    EXPECT_EQ(hold.type, fmuImport::Type::Boolean);
    EXPECT_EQ(hold.variability, fmuImport::Variability::discrete);
    EXPECT_EQ(hold.start, 0.0);
    EXPECT_EQ(hold.startString, "false");

    EXPECT_EQ(fmu.variable("label").startString, "lag");
    EXPECT_EQ(fmu.variable("stepCount").type, fmuImport::Type::Integer);

    EXPECT_TRUE(fmu.hasVariable("u"));
    EXPECT_FALSE(fmu.hasVariable("A.F[1]"));
    try {
        fmu.variable("A.F[1]");
        ADD_FAILURE() << "no Error for an unknown variable";
    } catch (const fmuImport::Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "FMU '" + fmuPath("firstOrderLag")
                      + "' has no variable 'A.F[1]'");
    }
}

TEST(FmuLoad, ResourceLocationIsAFileUriInTheUnpackDirectory)
{
    const fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
    EXPECT_EQ(fmu.resourceLocation(),
              "file://" + fmu.unpackDirectory() + "/resources");
}

TEST(FmuLoad, RemovesItsDirectoryWhenDestroyed)
{
    fixtures::PrivateTmpDir tmp;
    std::string directory;
    {
        const fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
        directory = fmu.unpackDirectory();
        EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(directory)
                                            / "modelDescription.xml"));
        EXPECT_EQ(std::filesystem::path(directory).parent_path(), tmp.path());
    }
    EXPECT_FALSE(std::filesystem::exists(directory));
    EXPECT_TRUE(tmp.contents().empty());
}

TEST(FmuLoad, MovedFmuKeepsItsFiles)
{
    fmuImport::Fmu first(fmuPath("firstOrderLag"));
    const std::string directory = first.unpackDirectory();
    fmuImport::Fmu second(std::move(first));
    EXPECT_TRUE(std::filesystem::exists(directory));
    EXPECT_EQ(second.modelDescription().modelIdentifier, "firstOrderLag");
}

TEST(FileSha256, GivesTheDigestAsSha256sumPrintsIt)
{
    fixtures::PrivateTmpDir tmp;
    const std::string abc = (tmp.path() / "abc").string();
    std::ofstream(abc) << "abc";
    EXPECT_EQ(
        fmuImport::fileSha256(abc),
        "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    const std::string empty = (tmp.path() / "empty").string();
    std::ofstream(empty).close();
    EXPECT_EQ(
        fmuImport::fileSha256(empty),
        "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    fixtures::expectErrorSaying(
        [] { fmuImport::fileSha256("/nonexistent/x.fmu"); },
        "cannot read '/nonexistent/x.fmu' for its SHA-256",
        "no error for a missing file");
}

TEST(FmuLoadError, MissingFile)
{
    expectLoadError(fmuPath("doesNotExist"), {"does not exist"});
}

TEST(FmuLoadError, NotAZip)
{
    expectLoadError(fmuPath("notAZip"), {"cannot be opened as a zip archive"});
}

TEST(FmuLoadError, NoModelDescription)
{
    expectLoadError(fmuPath("noModelDescription"),
                    {"has no modelDescription.xml"});
}

TEST(FmuLoadError, NotWellFormedXml)
{
    expectLoadError(fmuPath("badXml"), {"not well-formed XML"});
}

TEST(FmuLoadError, WrongFmiVersion)
{
    expectLoadError(fmuPath("wrongFmiVersion"),
                    {"fmiVersion is '1.0'", "only FMI 2.0"});
}

TEST(FmuLoadError, ModelExchangeOnly)
{
    expectLoadError(fmuPath("modelExchangeOnly"),
                    {"no <CoSimulation> element"});
}

TEST(FmuLoadError, BinaryMissing)
{
    expectLoadError(fmuPath("binaryMissing"),
                    {"has no binary binaries/linux64/firstOrderLag.so"});
}

TEST(FmuLoadError, MissingFmi2Function)
{
    expectLoadError(fmuPath("missingSymbol"),
                    {"does not export fmi2GetStringStatus"});
}

// firstOrderLag.fmu copied to <name>.fmu with `entry` added: loading it
// fails, naming the file and saying `message`
void expectEntryRefused(const std::string& name,
                        const fixtures::ZipEntry& entry,
                        const std::string& message)
{
    const std::string path = fmuPath(name);
    fixtures::copyWithEntries(fmuPath("firstOrderLag"), path, {entry});
    expectLoadError(path, {message});
}

TEST(FmuLoadError, EntryWithParentComponent)
{
    expectEntryRefused(
        "hostileParent", {"resources/../../escaped.txt", "x", false},
        "archive entry 'resources/../../escaped.txt' has a '..' component");
}

TEST(FmuLoadError, EntryWithAbsolutePath)
{
    expectEntryRefused("hostileAbsolute", {"/tmp/escaped.txt", "x", false},
                       "archive entry '/tmp/escaped.txt' has an absolute path");
}

// Two entries named modelDescription.xml: which one a tool reads would
// depend on the tool (the first, the last), so no tool may read either.
TEST(FmuLoadError, DuplicateModelDescription)
{
    const std::string path = fmuPath("duplicateDescription");
    fixtures::copyWithEntries(
        fmuPath("firstOrderLag"), path,
        {{"modelDescription.xmX", "<fmiModelDescription fmiVersion=\"2.0\"/>",
          false}});
    fixtures::renameEntry(path, "modelDescription.xmX", "modelDescription.xml");
    expectLoadError(path,
                    {"archive entry 'modelDescription.xml' appears twice"});
}

TEST(FmuLoadError, SymbolicLinkEntry)
{
    expectEntryRefused("hostileSymlink",
                       {"resources/passwd", "/etc/passwd", true},
                       "archive entry 'resources/passwd' is a symbolic link");
}

} // namespace

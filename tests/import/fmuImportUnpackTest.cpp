// What the importer unpacks, and how much: only modelDescription.xml, the
// binary and resources/, within the limits of Unzip.hpp, refused before
// anything is written when the zip directory declares too much, and stopped
// while writing when it lies.
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

using fixtures::fmuPath;

const std::uint64_t MiB = 1 << 20;

// Loads path expecting Error with every fragment in its message, while no
// file may grow past one MiB (the archives' own entries are smaller); the
// private TMPDIR must be empty afterwards.
void expectRefused(const std::string& path,
                   const std::vector<std::string>& fragments)
{
    fixtures::PrivateTmpDir tmp;
    {
        const fixtures::FileSizeLimit limit(MiB);
        try {
            fmuImport::Fmu fmu(path);
            ADD_FAILURE() << "loading " << path << " did not throw";
        } catch (const fmuImport::Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("FMU '" + path + "'"), std::string::npos)
                << message;
            for (const std::string& fragment : fragments)
                EXPECT_NE(message.find(fragment), std::string::npos)
                    << "missing '" << fragment << "' in: " << message;
        }
    }
    EXPECT_TRUE(tmp.contents().empty()) << "the importer left files in TMPDIR";
}

TEST(FmuUnpack, ZipBombIsRefusedBeforeWriting)
{
    const std::string path = fmuPath("zipBomb");
    fixtures::copyWithEntries(fmuPath("firstOrderLag"), path, {});
    fixtures::addZeroEntry(path, "resources/zeros.bin", 300 * MiB);
    ASSERT_LT(std::filesystem::file_size(path), MiB)
        << "the fixture should stay small on disk";
    expectRefused(
        path,
        {"archive entry 'resources/zeros.bin' unpacks to 314572800 bytes, more than the limit of "
         "268435456 bytes per entry",
         "FMUIMPORT_MAX_UNPACK_BYTES"});
}

TEST(FmuUnpack, TotalLimitComesFromTheEnvironment)
{
    const std::string path = fmuPath("twoHalves");
    fixtures::copyWithEntries(fmuPath("firstOrderLag"), path, {});
    fixtures::addZeroEntry(path, "resources/a.bin", 600 * 1024);
    fixtures::addZeroEntry(path, "resources/b.bin", 600 * 1024);
    const fixtures::ScopedEnv limit("FMUIMPORT_MAX_UNPACK_BYTES",
                                    std::to_string(MiB));
    expectRefused(
        path,
        {"archive entry 'resources/b.bin' (614400 bytes) brings the unpacked total to",
         "more than the limit of 1048576 bytes in total",
         "FMUIMPORT_MAX_UNPACK_BYTES"});
}

TEST(FmuUnpack, LyingZipDirectoryIsStoppedWhileWriting)
{
    const std::string path = fmuPath("lyingSize");
    fixtures::copyWithEntries(fmuPath("firstOrderLag"), path, {});
    fixtures::addZeroEntry(path, "resources/liar.bin", 4 * MiB);
    fixtures::patchDeclaredSize(path, "resources/liar.bin", 1000);
    expectRefused(
        path,
        {"archive entry 'resources/liar.bin' unpacks to more than the 1000 bytes the zip directory "
         "declares"});
}

TEST(FmuUnpack, MalformedLimitIsAnError)
{
    const fixtures::ScopedEnv limit("FMUIMPORT_MAX_UNPACK_BYTES", "1GiB");
    try {
        fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
        FAIL() << "a malformed limit was accepted";
    } catch (const fmuImport::Error& e) {
        EXPECT_EQ(
            std::string(e.what()),
            "environment variable FMUIMPORT_MAX_UNPACK_BYTES is '1GiB', expected a positive number of bytes");
    }
}

TEST(FmuUnpack, OnlyTheDescriptionTheBinaryAndResourcesAreUnpacked)
{
    const std::string path = fmuPath("extraEntries");
    fixtures::copyWithEntries(
        fmuPath("firstOrderLag"), path,
        {{"documentation/index.html", "<html/>", false},
         {"sources/model.c", "int x;", false},
         {"binaries/win64/firstOrderLag.dll", "MZ", false},
         {"resources/tables/table.csv", "1,2\n", false}});
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu(path);
    const std::filesystem::path dir = fmu.unpackDirectory();
    EXPECT_TRUE(std::filesystem::exists(dir / "modelDescription.xml"));
    EXPECT_TRUE(
        std::filesystem::exists(dir / "binaries/linux64/firstOrderLag.so"));
    EXPECT_TRUE(std::filesystem::exists(dir / "resources/tables/table.csv"));
    EXPECT_FALSE(std::filesystem::exists(dir / "documentation"));
    EXPECT_FALSE(std::filesystem::exists(dir / "sources"));
    EXPECT_FALSE(std::filesystem::exists(dir / "binaries/win64"));
}

TEST(FmuUnpack, ModelIdentifierMustBeACIdentifier)
{
    const std::string path = fmuPath("identifierEscapes");
    fixtures::writeArchive(
        path,
        {{"modelDescription.xml",
          "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"m\" guid=\"g\">"
          "<CoSimulation modelIdentifier=\"../../../tmp/evil\"/></fmiModelDescription>",
          false},
         {"tmp/evil.so", "not a library", false}});
    expectRefused(
        path, {"modelIdentifier '../../../tmp/evil' is not a C identifier"});
}

} // namespace

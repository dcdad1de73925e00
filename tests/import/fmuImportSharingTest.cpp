// One file loaded several times in one process is unpacked and loaded
// once, and an FMU that can be instantiated only once per process gets one
// live instance at a time.
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

namespace {

using fixtures::fmuPath;

TEST(FmuSharing, OneFileSharesOneUnpackDirectory)
{
    fixtures::PrivateTmpDir tmp;
    const std::string path = fmuPath("firstOrderLag");
    {
        const fmuImport::Fmu first(path);
        const std::string otherSpelling
            = std::string(FIXTURE_FMU_DIR) + "/./firstOrderLag.fmu";
        const fmuImport::Fmu second(otherSpelling);
        EXPECT_EQ(first.unpackDirectory(), second.unpackDirectory());
        EXPECT_EQ(tmp.contents().size(), 1u);
        EXPECT_EQ(second.path(),
                  otherSpelling); // each Fmu keeps the name it was given
        EXPECT_EQ(second.modelDescription().guid,
                  first.modelDescription().guid);
    }
    EXPECT_TRUE(tmp.contents().empty());
}

TEST(FmuSharing, InstancesKeepTheSharedCopyAlive)
{
    fixtures::PrivateTmpDir tmp;
    std::unique_ptr<fmuImport::Instance> instance;
    std::string directory;
    {
        const fmuImport::Fmu first(fmuPath("firstOrderLag"));
        directory = first.unpackDirectory();
        instance.reset(new fmuImport::Instance(first, "lag1"));
    }
    const fmuImport::Fmu again(fmuPath("firstOrderLag"));
    EXPECT_EQ(again.unpackDirectory(), directory);
    instance.reset();
    EXPECT_TRUE(std::filesystem::exists(directory));
}

TEST(FmuSharing, RewrittenFileIsLoadedAnew)
{
    fixtures::PrivateTmpDir tmp;
    const std::string path
        = (tmp.path().parent_path() / (tmp.path().filename().string() + ".fmu"))
              .string();
    fixtures::copyWithEntries(fmuPath("firstOrderLag"), path, {});
    const fmuImport::Fmu before(path);
    fixtures::copyWithEntries(fmuPath("firstOrderLag"), path,
                              {{"resources/new.txt", "new", false}});
    const fmuImport::Fmu after(path);
    EXPECT_NE(before.unpackDirectory(), after.unpackDirectory());
    EXPECT_TRUE(std::filesystem::exists(
        std::filesystem::path(after.unpackDirectory()) / "resources/new.txt"));
    std::filesystem::remove(path);
}

TEST(FmuSharing, OnceOnlyFmuRefusesASecondLiveInstance)
{
    const fmuImport::Fmu fmu(fmuPath("onceOnly"));
    EXPECT_TRUE(fmu.modelDescription().canBeInstantiatedOnlyOncePerProcess);
    std::unique_ptr<fmuImport::Instance> first(
        new fmuImport::Instance(fmu, "first"));
    const fmuImport::Fmu sameFile(
        fmuPath("onceOnly")); // shares the binary, so the same rule
    for (const fmuImport::Fmu* f : {&fmu, &sameFile}) {
        try {
            fmuImport::Instance second(*f, "second");
            ADD_FAILURE() << "a second instance was made";
        } catch (const fmuImport::Error& e) {
            EXPECT_EQ(
                std::string(e.what()),
                "FMU '" + fmuPath("onceOnly")
                    + "' declares canBeInstantiatedOnlyOncePerProcess=\"true\" and an instance of it exists "
                      "already: cannot instantiate 'second' (free the other instance first)");
        }
    }
    first.reset();
    fmuImport::Instance third(fmu, "third"); // the first one is gone
    third.setupExperiment(0.0);
}

TEST(FmuSharing, OrdinaryFmuHasManyInstances)
{
    const fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
    EXPECT_FALSE(fmu.modelDescription().canBeInstantiatedOnlyOncePerProcess);
    fmuImport::Instance a(fmu, "a"), b(fmu, "b");
    a.setupExperiment(0.0);
    b.setupExperiment(0.0);
}

} // namespace

// Unpack directories are removed on the paths that skip destructors: exit()
// (OpenFOAM's FatalError), fatal signals and termination requests, with
// handlers of the host installed before or after the importer's. Each case
// runs cleanupHelper.cpp as a child process with TMPDIR set to an empty
// directory.
#include "zipFixtures.hpp"

#include <gtest/gtest.h>

#include "fmuImport/fmuImport.hpp"

#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace {

struct Outcome {
    bool signalled = false;
    int code = 0; // exit status, or the signal that ended the child
    std::string marker; // what the child's handler wrote
    std::vector<std::string> leftovers;
};

Outcome runHelper(const std::string& how)
{
    fixtures::PrivateTmpDir tmp; // sets TMPDIR, which the child inherits
    const std::string marker = (tmp.path().parent_path()
                                / (tmp.path().filename().string() + ".marker"))
                                   .string();
    const std::string fmu = fixtures::fmuPath("firstOrderLag");
    std::vector<std::string> args = {CLEANUP_HELPER, fmu, how, marker};
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);

    pid_t pid = 0;
    if (posix_spawn(&pid, CLEANUP_HELPER, nullptr, nullptr, argv.data(),
                    environ)
        != 0)
        throw std::runtime_error(std::string("cannot start ") + CLEANUP_HELPER);
    int status = 0;
    waitpid(pid, &status, 0);

    Outcome outcome;
    outcome.signalled = WIFSIGNALED(status);
    outcome.code = outcome.signalled ? WTERMSIG(status) : WEXITSTATUS(status);
    std::ifstream in(marker);
    std::stringstream text;
    text << in.rdbuf();
    outcome.marker = text.str();
    std::remove(marker.c_str());
    outcome.leftovers = tmp.contents();
    return outcome;
}

std::string describe(const Outcome& o)
{
    std::string s = o.signalled ? "killed by signal " + std::to_string(o.code)
            + " (" + strsignal(o.code) + ")"
                                : "exit status " + std::to_string(o.code);
    for (const std::string& name : o.leftovers)
        s += ", left " + name;
    return s;
}

void expectSignalled(const Outcome& o, int sig)
{
    EXPECT_TRUE(o.signalled && o.code == sig) << describe(o);
    EXPECT_TRUE(o.leftovers.empty()) << describe(o);
}

TEST(UnpackCleanup, ExitRemovesTheUnpackDirectory)
{
    const Outcome o = runHelper("exit");
    EXPECT_TRUE(!o.signalled && o.code == 1) << describe(o);
    EXPECT_TRUE(o.leftovers.empty()) << describe(o);
}

TEST(UnpackCleanup, SigtermRemovesTheUnpackDirectory)
{
    expectSignalled(runHelper("term"), SIGTERM);
}

TEST(UnpackCleanup, SigintRemovesTheUnpackDirectory)
{
    expectSignalled(runHelper("int"), SIGINT);
}

TEST(UnpackCleanup, SegmentationFaultRemovesTheUnpackDirectory)
{
    expectSignalled(runHelper("segv"), SIGSEGV);
}

TEST(UnpackCleanup, AbortRemovesTheUnpackDirectory)
{
    expectSignalled(runHelper("abort"), SIGABRT);
}

TEST(UnpackCleanup, IllegalInstructionRemovesTheUnpackDirectory)
{
    expectSignalled(runHelper("ill"), SIGILL);
}

// runHelper(mode) ended by `signal`, the unpack directory removed, and the
// host's own handler ran
void expectHostHandlerRan(const char* mode, int signal)
{
    const Outcome o = runHelper(mode);
    expectSignalled(o, signal);
    EXPECT_EQ(o.marker, "handler ran\n");
}

// The host handles SIGSEGV on an alternate stack (fmusim does, to report a
// stack overflow in an FMU): the importer's handler must run there too.
TEST(UnpackCleanup, StackOverflowWithTheHostsAlternateStack)
{
    expectHostHandlerRan("stack-overflow", SIGSEGV);
}

TEST(UnpackCleanup, HostHandlerInstalledBeforeStillRuns)
{
    expectHostHandlerRan("term-before", SIGTERM);
}

TEST(UnpackCleanup, HostHandlerInstalledAfterStillRuns)
{
    expectHostHandlerRan("term-after", SIGTERM);
}

TEST(UnpackCleanup, HostSegvHandlerInstalledAfterStillRuns)
{
    expectHostHandlerRan("segv-after", SIGSEGV);
}

TEST(UnpackCleanup, HostHandlerThatGoesOnKeepsTheFilesUntilTheEnd)
{
    const Outcome o = runHelper("term-graceful");
    EXPECT_TRUE(!o.signalled && o.code == 0) << describe(o);
    EXPECT_EQ(o.marker, "handler ran\n");
    EXPECT_TRUE(o.leftovers.empty()) << describe(o);
}

// The process id of a process that has ended: a child that exits at once.
pid_t deadProcessId()
{
    pid_t pid = 0;
    char true_[] = "/bin/true";
    char* argv[] = {true_, nullptr};
    if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv, environ) != 0)
        throw std::runtime_error("cannot start /bin/true");
    int status = 0;
    waitpid(pid, &status, 0);
    return pid;
}

// A killed run (SIGKILL, a node that went down) leaves its unpack folder
// behind: the next process that unpacks into the same temporary folder
// removes the folders of the importer's naming whose process has ended and
// that belong to its user, and nothing else.
TEST(UnpackCleanup, FoldersOfEndedProcessesAreRemovedAtTheFirstUnpack)
{
    namespace fs = std::filesystem;
    fixtures::PrivateTmpDir tmp;
    const std::string dead = std::to_string(deadProcessId());
    const std::string alive = std::to_string(getppid());
    const fs::path outside = tmp.path().parent_path()
        / (tmp.path().filename().string() + ".outside");
    fs::create_directories(outside / "keep");
    for (const std::string& name :
         {"fmuImport-" + dead + "-aB3xY9", "fmuImport-" + alive + "-aB3xY9",
          "fmuImport-x" + dead + "-aB3xY9", "fmuImport-" + dead + "-a/b",
          "other-" + dead + "-aB3xY9", "fmuImport-" + dead + "-toolong1"}) {
        fs::create_directories(tmp.path() / name / "binaries");
        std::ofstream(tmp.path() / name / "binaries" / "x.so") << "x";
    }
    fs::create_directory_symlink(
        outside, tmp.path() / ("fmuImport-" + dead + "-link00"));
    std::ofstream(tmp.path() / ("fmuImport-" + dead + "-file00")) << "x";
    // Owned by another user: only root can make one
    const bool asRoot = geteuid() == 0;
    const fs::path foreign = tmp.path() / ("fmuImport-" + dead + "-other0");
    if (asRoot) {
        fs::create_directory(foreign);
        ASSERT_EQ(chown(foreign.c_str(), 65534, 65534), 0);
    }

    {
        const fmuImport::Fmu fmu(fixtures::fmuPath("firstOrderLag"));
        std::vector<std::string> left = tmp.contents();
        std::sort(left.begin(), left.end());
        const std::string own
            = fs::path(fmu.unpackDirectory()).filename().string();
        std::vector<std::string> expected = {own,
                                             "fmuImport-" + alive + "-aB3xY9",
                                             "fmuImport-x" + dead + "-aB3xY9",
                                             "fmuImport-" + dead + "-a",
                                             "other-" + dead + "-aB3xY9",
                                             "fmuImport-" + dead + "-toolong1",
                                             "fmuImport-" + dead + "-link00",
                                             "fmuImport-" + dead + "-file00"};
        if (asRoot)
            expected.push_back(foreign.filename().string());
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(left, expected);
    }
    EXPECT_TRUE(fs::exists(outside / "keep"));
    fs::remove_all(outside);
}

} // namespace

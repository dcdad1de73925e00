// An instance in a child process (Isolation::process) whose FMU crashes or
// hangs: the call throws LostCall naming the FMU, the instance, the fmi2
// function and the time, and this process goes on. faultySpring
// (tests/fmusim/fixtures/testSpring.c) crashes (SIGSEGV) or never returns
// in the first fmi2DoStep from crashTime or hangTime on.
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

#include <dirent.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

namespace {

using fixtures::fmuPath;

struct FaultySpring {
    fmuImport::Fmu fmu;
    fmuImport::Instance instance;

    // Steps of 1/4 s, exact in binary, the fault parameter set
    FaultySpring(const fmuImport::FmuOptions& options, const char* fault,
                 double time)
        : fmu(fmuPath("faultySpring"), options),
          instance(fmu, "spring",
                   [](const std::string&, int, const std::string&,
                      const std::string&) {})
    {
        instance.setupExperiment(0.0);
        instance.setReal({fmu.variable(fault).valueReference}, {time});
        instance.enterInitializationMode();
        instance.exitInitializationMode();
    }

    // Steps until the call does not come back; its LostCall
    fmuImport::LostCall stepUntilLost()
    {
        for (int k = 0; k < 8; ++k) {
            try {
                instance.doStep(0.25 * k, 0.25);
                instance.getReal({fmu.variable("A.F[1]").valueReference});
            } catch (const fmuImport::LostCall& lost) {
                return lost;
            }
        }
        throw std::runtime_error("the FMU did not fail");
    }
};

// No child process left: every one was waited for.
bool noChildLeft()
{
    return waitpid(-1, nullptr, WNOHANG) == -1 && errno == ECHILD;
}

TEST(ChildProcess, CrashIsALostCallThatNamesTheCall)
{
    {
        FaultySpring spring({fmuImport::Isolation::process, 0, ""}, "crashTime",
                            0.5);
        const fmuImport::LostCall lost = spring.stepUntilLost();
        EXPECT_EQ(lost.reason(), fmuImport::LostCall::Reason::crashed);
        EXPECT_EQ(std::string(lost.what()),
                  "the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep "
                  "at t = 0.5 in FMU '"
                      + fmuPath("faultySpring") + "', instance 'spring'");
        // The instance is gone: every later call says so
        try {
            spring.instance.getReal({0});
            ADD_FAILURE() << "a call after the crash did not throw";
        } catch (const fmuImport::LostCall& again) {
            EXPECT_EQ(std::string(again.what()), lost.what());
        }
    }
    EXPECT_TRUE(noChildLeft());
    // and this process goes on, with new instances
    FaultySpring next({fmuImport::Isolation::process, 0, ""}, "crashTime",
                      1e300);
    next.instance.doStep(0.0, 0.25);
}

TEST(ChildProcess, CallOverTheTimeLimitIsKilled)
{
    const auto start = std::chrono::steady_clock::now();
    {
        FaultySpring spring(
            {fmuImport::Isolation::process, 0.5, "restraint spring"},
            "hangTime", 0.75);
        const fmuImport::LostCall lost = spring.stepUntilLost();
        EXPECT_EQ(lost.reason(), fmuImport::LostCall::Reason::timedOut);
        EXPECT_EQ(std::string(lost.what()),
                  "time-out: fmi2DoStep at t = 0.75 in FMU '"
                      + fmuPath("faultySpring")
                      + "' of restraint spring did not return within 0.5 s");
    }
    EXPECT_LT(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count(),
        5.0);
    EXPECT_TRUE(noChildLeft());
}

// The helper program this process started; -1 when there is none
pid_t workerChild()
{
    DIR* proc = opendir("/proc");
    pid_t found = -1;
    while (const dirent* e = proc ? readdir(proc) : nullptr) {
        std::ifstream stat(std::string("/proc/") + e->d_name + "/stat");
        std::string pid, comm, state;
        long parent = 0;
        if (stat >> pid >> comm >> state >> parent && parent == getpid()
            && comm == "(fmuImportWorker)")
            found = std::atoi(pid.c_str());
    }
    if (proc)
        closedir(proc);
    return found;
}

// A child killed while its FMU hangs in a call, without a time limit: the
// call ends within moments, named; it does not wait for ever on the page.
TEST(ChildProcess, DeathInAHangingCallIsNoticedAtOnce)
{
    FaultySpring spring({fmuImport::Isolation::process, 0, ""}, "hangTime",
                        0.5);
    const pid_t child = workerChild();
    ASSERT_GT(child, 0);
    using Clock = std::chrono::steady_clock;
    Clock::time_point killed;
    std::thread killer([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        killed = Clock::now();
        ::kill(child, SIGKILL);
    });
    const fmuImport::LostCall lost = spring.stepUntilLost();
    const Clock::time_point end = Clock::now();
    killer.join();
    const double after = std::chrono::duration<double>(end - killed).count();
    EXPECT_EQ(std::string(lost.what()),
              "the FMU crashed (SIGKILL, killed) in fmi2DoStep at t = 0.5 in "
              "FMU '"
                  + fmuPath("faultySpring") + "', instance 'spring'");
    EXPECT_LT(after, 0.5);
    EXPECT_TRUE(noChildLeft());
}

// A time limit does not end calls that take less, however many
TEST(ChildProcess, TimeLimitLetsShorterCallsThrough)
{
    FaultySpring spring({fmuImport::Isolation::process, 0.5, ""}, "hangTime",
                        1e300);
    for (int k = 0; k < 200; ++k)
        spring.instance.doStep(0.25 * k, 0.25);
}

// Requests and replies longer than the call page holds (64 KiB) go on the
// socket: 10000 values, 120 kB of a set, 80 kB of a get
TEST(ChildProcess, LongMessagesGoThrough)
{
    FaultySpring spring({fmuImport::Isolation::process, 0, ""}, "crashTime",
                        1e300);
    const unsigned int force = spring.fmu.variable("A.F[1]").valueReference;
    const std::vector<unsigned int> vrs(10000, force);
    spring.instance.doStep(0.0, 0.25);
    const std::vector<double> values = spring.instance.getReal(vrs);
    ASSERT_EQ(values.size(), vrs.size());
    EXPECT_EQ(values.front(), spring.instance.getReal({force}).front());
    EXPECT_EQ(values.back(), values.front());
    spring.instance.reset();
    const unsigned int crash = spring.fmu.variable("crashTime").valueReference;
    spring.instance.setReal(std::vector<unsigned int>(10000, crash),
                            std::vector<double>(10000, 0.5));
    spring.instance.setupExperiment(0.0);
    spring.instance.enterInitializationMode();
    spring.instance.exitInitializationMode();
    EXPECT_EQ(spring.stepUntilLost().reason(),
              fmuImport::LostCall::Reason::crashed);
}

TEST(ChildProcess, ErrorOfTheBinaryComesWithTheFirstInstance)
{
    const fmuImport::Fmu fmu(fmuPath("missingSymbol"),
                             {fmuImport::Isolation::process, 0, ""});
    fixtures::expectErrorSaying(
        [&] { fmuImport::Instance instance(fmu, "lag1"); },
        "does not export fmi2GetStringStatus",
        "instantiated an FMU with a missing function");
    EXPECT_TRUE(noChildLeft());
}

TEST(ChildProcess, MissingHelperProgramIsNamed)
{
    const fixtures::ScopedEnv worker("FMUIMPORT_WORKER", "/nonexistent/worker");
    try {
        FaultySpring spring({fmuImport::Isolation::process, 0, ""}, "crashTime",
                            1e300);
        ADD_FAILURE() << "an instance without its helper program";
    } catch (const fmuImport::Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "the environment variable FMUIMPORT_WORKER names "
                  "'/nonexistent/worker', which is not an executable file");
    }
}

} // namespace

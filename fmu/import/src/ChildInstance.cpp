#include "ChildInstance.hpp"

#include "CallReport.hpp"
#include "LocalInstance.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>
#include <limits>
#include <thread>

extern char** environ;

namespace fmuImport {

using protocol::FrameWriter;
using protocol::Op;

namespace {

const double noTime = std::numeric_limits<double>::quiet_NaN();

// A file descriptor at 10 or above, close-on-exec: posix_spawn's dup2 to 3
// and 4 then never overwrites the other one.
int highDescriptor(int fd)
{
    const int high = fcntl(fd, F_DUPFD_CLOEXEC, 10);
    ::close(fd);
    return high;
}

std::string systemError(const std::string& what)
{
    return what + ": " + std::strerror(errno);
}

} // namespace

ChildInstance::ChildInstance(std::shared_ptr<Fmu::Impl> fmuImpl,
                             const std::string& path,
                             const std::string& instanceName, Logger logger,
                             bool loggingOn, const FmuOptions& options)
    : Impl(std::move(fmuImpl), path, instanceName), logger_(std::move(logger)),
      site_(siteText(path, instanceName, options.owner)),
      timeout_(options.timeout)
{
    const std::string program = workerProgram();
    const std::string cannot = "FMU '" + fmuPath + "', instance '" + name
        + "': cannot start its process " + program;

    int ends[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
        throw Error(systemError(cannot + ": socketpair"));
    socket_ = highDescriptor(ends[0]);
    const int childEnd = highDescriptor(ends[1]);
    int pageFile = memfd_create("fmuImport-call", MFD_CLOEXEC);
    if (pageFile >= 0)
        pageFile = highDescriptor(pageFile);
    if (socket_ < 0 || childEnd < 0 || pageFile < 0
        || ftruncate(pageFile, sizeof(protocol::CallPage)) != 0) {
        const std::string reason = systemError(cannot + ": file descriptors");
        ::close(childEnd);
        ::close(pageFile);
        throw Error(reason);
    }
    void* page = mmap(nullptr, sizeof(protocol::CallPage),
                      PROT_READ | PROT_WRITE, MAP_SHARED, pageFile, 0);
    if (page == MAP_FAILED) {
        const std::string reason = systemError(cannot + ": mmap");
        ::close(childEnd);
        ::close(pageFile);
        throw Error(reason);
    }
    page_ = new (page) protocol::CallPage;

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, childEnd, protocol::socketFd);
    posix_spawn_file_actions_adddup2(&actions, pageFile, protocol::pageFd);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null",
                                     O_RDONLY, 0);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGPIPE})
        sigaddset(&defaults, s);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes,
                             POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    const std::string parent = std::to_string(getpid());
    std::vector<char*> argv {const_cast<char*>(program.c_str()),
                             const_cast<char*>(parent.c_str()), nullptr};
    const int spawned = posix_spawn(&pid_, program.c_str(), &actions,
                                    &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ::close(childEnd);
    ::close(pageFile);
    if (spawned != 0) {
        pid_ = -1;
        errno = spawned;
        throw Error(systemError(cannot));
    }
    fcntl(socket_, F_SETFL, fcntl(socket_, F_GETFL) | O_NONBLOCK);

    try {
        request(Op::load, noTime, true)
            .put(fmu->root.string())
            .put(fmuPath)
            .finish();
        exchange();
        request(Op::instantiate, noTime, true)
            .put(name)
            .put(std::uint8_t(loggingOn))
            .finish();
        exchange();
    } catch (...) {
        // No destructor runs: the child ends at an empty message, or at
        // the end of its socket
        if (!lost_) {
            page_->request.length = 0;
            protocol::post(page_->request);
        }
        if (socket_ >= 0)
            ::close(socket_);
        if (!lost_)
            reap(3);
        munmap(page_, sizeof(protocol::CallPage));
        throw;
    }
}

ChildInstance::~ChildInstance()
{
    if (pid_ > 0 && !lost_) {
        try {
            request(Op::freeInstance, time, true).finish();
            exchange();
        } catch (const std::exception& e) {
            std::cerr << reportPrefix() << e.what() << '\n';
        }
    }
    if (socket_ >= 0)
        ::close(socket_);
    if (pid_ > 0 && !lost_)
        reap(3);
    if (page_)
        munmap(page_, sizeof(protocol::CallPage));
}

FrameWriter ChildInstance::request(Op op, double t, bool reply, double endTime)
{
    checkAlive();
    stepDone_ = false;
    haveRead_ = false;
    sent_.push_back({++seq_, op, t, endTime});
    FrameWriter w(queue_, seq_);
    w.put(op).put(std::uint8_t(reply));
    return w;
}

void ChildInstance::checkAlive() const
{
    if (lost_)
        throw *lost_;
}

int ChildInstance::reap(double graceSeconds, bool* endedItself)
{
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    int status = 0;
    for (int i = 0;; ++i) {
        const pid_t r = waitpid(pid_, &status, WNOHANG);
        if (r == pid_ || (r < 0 && errno != EINTR)) {
            if (endedItself)
                *endedItself = true;
            return status;
        }
        if (std::chrono::duration<double>(Clock::now() - start).count()
            >= graceSeconds)
            break;
        std::this_thread::sleep_for(
            std::chrono::milliseconds(i < 100 ? 1 : 10));
    }
    ::kill(pid_, SIGKILL);
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) { }
    if (endedItself)
        *endedItself = false;
    return status;
}

void ChildInstance::lose(Fault fault, bool afterPost, const std::string& detail)
{
    if (fault != Fault::ended)
        ::kill(pid_, SIGKILL);
    ::close(socket_);
    socket_ = -1;
    // A child that died closed its socket a moment before it can be
    // waited for; one still running after a second closed its end itself.
    bool endedItself = false;
    const int status = reap(fault == Fault::ended ? 1 : 0, &endedItself);
    if (fault == Fault::ended && !endedItself)
        fault = Fault::closedChannel;
    const std::uint64_t started = page_->started.load();
    const std::uint64_t finished = page_->finished.load();
    const Sent* call = nullptr;
    for (const Sent& s : sent_)
        if (s.seq == started && started > finished)
            call = &s;
    if (!call && !sent_.empty() && (afterPost || fault != Fault::ended))
        call = &sent_.back();
    const int version = fmu->description.fmiMajorVersion;
    const char* function
        = call ? protocol::functionOf(call->op, version) : "a call";
    double t = call ? call->time : noTime;
    if (call && call->op == Op::doStep && page_->reading.load()) {
        // the read of the outputs after the step
        function = version == 3 ? "fmi3GetFloat64" : "fmi2GetReal";
        t = call->endTime;
    }

    SignalSafeText text;
    LostCall::Reason reason = LostCall::Reason::crashed;
    if (fault == Fault::timedOut) {
        reason = LostCall::Reason::timedOut;
        text << "time-out: ";
        describeCall(text, function, t, site_.c_str());
        text << " did not return within ";
        text.number(timeout_) << " s" << timeoutSource();
    } else if (fault != Fault::ended) {
        reason = LostCall::Reason::brokeChannel;
        if (fault == Fault::closedChannel)
            text << "the FMU closed its process's end of the channel";
        else
            text << "the channel to the FMU's process " << detail.c_str();
        text << " in ";
        describeCall(text, function, t, site_.c_str());
    } else {
        const bool exited = WIFEXITED(status);
        reason = exited ? LostCall::Reason::exited : LostCall::Reason::crashed;
        text << (call ? "the FMU " : "the FMU's process ")
             << (exited ? "exited (status " : "crashed (");
        if (exited)
            text << long(WEXITSTATUS(status));
        else
            describeSignal(text, WTERMSIG(status));
        text << ")";
        if (call) {
            text << " in ";
            describeCall(text, function, t, site_.c_str());
        } else {
            text << " outside any " << (version == 3 ? "fmi3" : "fmi2")
                 << " call" << site_.c_str();
        }
    }
    lost_ = std::make_shared<LostCall>(reason, text.c_str());
    throw *lost_;
}

} // namespace fmuImport

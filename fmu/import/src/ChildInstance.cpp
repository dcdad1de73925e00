#include "ChildInstance.hpp"

#include "CallReport.hpp"
#include "LocalInstance.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <thread>

extern char** environ;

namespace fmuImport {

using protocol::FrameReader;
using protocol::FrameWriter;
using protocol::Kind;
using protocol::Op;

namespace {

const char* const workerName = "fmuImportWorker";
const double noTime = std::numeric_limits<double>::quiet_NaN();

// How long the parent waits for a reply on the page (Protocol.hpp) before
// it sleeps on the socket
const int pageWaitMicroseconds = 50;

bool isProgram(const std::string& path)
{
    struct stat st;
    return !path.empty() && stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)
        && access(path.c_str(), X_OK) == 0;
}

std::string folderOf(const std::string& path)
{
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

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

std::string workerProgram()
{
    if (const char* given = std::getenv("FMUIMPORT_WORKER")) {
        if (!isProgram(given))
            throw Error(std::string("the environment variable FMUIMPORT_WORKER "
                                    "names '")
                        + given + "', which is not an executable file");
        return given;
    }
    std::vector<std::string> candidates;
    char self[4096];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n > 0)
        candidates.push_back(folderOf(std::string(self, n)) + "/" + workerName);
    Dl_info info;
    if (dladdr(reinterpret_cast<void*>(&workerProgram), &info)
        && info.dli_fname) {
        const std::string folder = folderOf(info.dli_fname);
        candidates.push_back(folder + "/" + workerName);
        candidates.push_back(folder + "/../bin/" + workerName);
    }
#ifdef FMUIMPORT_WORKER_PATH
    candidates.push_back(FMUIMPORT_WORKER_PATH);
#endif
    for (const std::string& c : candidates)
        if (isProgram(c))
            return c;
    const char* path = std::getenv("PATH");
    for (std::string rest = path ? path : ""; !rest.empty();) {
        const std::size_t colon = rest.find(':');
        const std::string folder = rest.substr(0, colon);
        rest = colon == std::string::npos ? "" : rest.substr(colon + 1);
        if (isProgram(folder + "/" + workerName))
            return folder + "/" + workerName;
    }
    std::string tried;
    for (const std::string& c : candidates)
        tried += (tried.empty() ? "" : ", ") + c;
    throw Error(std::string("the helper program ") + workerName
                + " that runs an FMU in a process of its own was not found ("
                + tried
                + ", nor on PATH): build it with the project, or set the "
                  "environment variable FMUIMPORT_WORKER to it");
}

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
        // No destructor runs: the child ends at the end of its socket
        if (socket_ >= 0)
            ::close(socket_);
        if (!lost_)
            reap();
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
        reap();
    if (page_)
        munmap(page_, sizeof(protocol::CallPage));
}

FrameWriter ChildInstance::request(Op op, double t, bool reply, double endTime)
{
    checkAlive();
    stepDone_ = false;
    haveRead_ = false;
    sent_.push_back({++seq_, op, t, endTime});
    FrameWriter w(queue_);
    w.put(op).put(std::uint8_t(reply)).put(seq_);
    return w;
}

void ChildInstance::checkAlive() const
{
    if (lost_)
        throw *lost_;
}

bool ChildInstance::sendQueue()
{
    std::size_t done = 0;
    while (done < queue_.size()) {
        const ssize_t n = ::send(socket_, queue_.data() + done,
                                 queue_.size() - done, MSG_NOSIGNAL);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && errno == EAGAIN) {
            // The child reads its requests as it runs them: wait for room
            pollfd p {socket_, POLLOUT, 0};
            const int timeoutMs = timeout_ > 0
                ? static_cast<int>(std::ceil(timeout_ * 1000))
                : -1;
            if (::poll(&p, 1, timeoutMs) == 0)
                lose(true);
            continue;
        }
        return false;
    }
    queue_.clear();
    return true;
}

bool ChildInstance::waitForReply()
{
    pollfd p {socket_, POLLIN, 0};
    if (!(timeout_ > 0)) {
        while (::poll(&p, 1, -1) < 0 && errno == EINTR) { }
        return true;
    }
    // The limit is per call: while the child moves on to its next request,
    // the clock starts again.
    using Clock = std::chrono::steady_clock;
    const std::chrono::duration<double> limit(timeout_);
    std::uint64_t progress = page_->started.load() + page_->finished.load();
    Clock::time_point deadline
        = Clock::now() + std::chrono::duration_cast<Clock::duration>(limit);
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - Clock::now());
        const int n = ::poll(
            &p, 1, static_cast<int>(std::max<long>(0, left.count() + 1)));
        if (n > 0)
            return true;
        if (n < 0 && errno == EINTR)
            continue;
        const std::uint64_t now
            = page_->started.load() + page_->finished.load();
        if (now != progress) {
            progress = now;
            deadline = Clock::now()
                + std::chrono::duration_cast<Clock::duration>(limit);
            continue;
        }
        if (Clock::now() >= deadline)
            return false;
    }
}

FrameReader ChildInstance::exchange()
{
    if (!sendQueue())
        lose(false);
    protocol::waitOnPage(page_->finished, seq_, pageWaitMicroseconds);
    for (;;) {
        FrameReader frame(nullptr, nullptr);
        while (inbox_.next(frame)) {
            if (frame.get<Kind>() == Kind::log) {
                const int status = frame.get<std::int32_t>();
                const std::string instance = frame.getString();
                const std::string category = frame.getString();
                const std::string message = frame.getString();
                if (logger_)
                    logger_(instance, status, category, message);
                else
                    logToStderr(instance, status, category, message,
                                fmu->description.fmiMajorVersion == 3);
                continue;
            }
            sent_.clear();
            const bool ok = frame.get<std::uint8_t>() != 0;
            if (!ok) {
                const std::string error = frame.getString();
                lastMessage_ = frame.getString();
                throw Error(error);
            }
            lastMessage_ = frame.getString();
            return frame;
        }
        const long n = inbox_.fill(socket_);
        if (n > 0)
            continue;
        if (n < 0 && errno == EAGAIN) {
            if (!waitForReply())
                lose(true);
            continue;
        }
        lose(false);
    }
}

int ChildInstance::reap()
{
    int status = 0;
    for (int i = 0; i < 300; ++i) {
        const pid_t r = waitpid(pid_, &status, WNOHANG);
        if (r == pid_ || (r < 0 && errno != EINTR))
            return status;
        std::this_thread::sleep_for(
            std::chrono::milliseconds(i < 100 ? 1 : 10));
    }
    ::kill(pid_, SIGKILL);
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) { }
    return status;
}

void ChildInstance::lose(bool timedOut)
{
    if (timedOut)
        ::kill(pid_, SIGKILL);
    ::close(socket_);
    socket_ = -1;
    const int status = reap();
    const std::uint64_t started = page_->started.load();
    const std::uint64_t finished = page_->finished.load();
    const Sent* call = nullptr;
    for (const Sent& s : sent_)
        if (s.seq == started && started > finished)
            call = &s;
    if (timedOut && !call && !sent_.empty())
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
    if (timedOut) {
        reason = LostCall::Reason::timedOut;
        text << "time-out: ";
        describeCall(text, function, t, site_.c_str());
        text << " did not return within ";
        text.number(timeout_) << " s" << timeoutSource();
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
            text << " outside any fmi2 call" << site_.c_str();
        }
    }
    lost_ = std::make_shared<LostCall>(reason, text.c_str());
    throw *lost_;
}

} // namespace fmuImport

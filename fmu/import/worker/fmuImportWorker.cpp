// fmuImportWorker: runs one instance of an FMU for another process
// (fmuImport's Isolation::process; ChildInstance.hpp starts it).
//
//   fmuImportWorker <parent pid>
//
// with the socket as file descriptor 3 and the call page as 4 (Channel.hpp).
// It maps the page, moves the socket to a high, close-on-exec descriptor
// and closes both numbers, so that an FMU that writes to descriptor 3, or
// closes the low ones, misses them. It waits for requests in the page
// (Protocol.hpp), loads the binary from the directory the parent unpacked
// the FMU in, runs each request with fmuImport's in-process Instance, whose
// errors read as they would in the parent, posts the reply in the page and
// sends the FMU's log messages on the socket as they come. It ends when
// the parent closes the socket, frees the instance, or dies
// (PR_SET_PDEATHSIG). Terminal signals (SIGINT, SIGTERM, SIGHUP, SIGQUIT)
// are the parent's to act on: ignored here. Not a program to run by hand.
#include "Channel.hpp"
#include "FmuImpl.hpp"
#include "Protocol.hpp"

#include "fmuImport/fmuImport.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

namespace {

using namespace fmuImport;
using protocol::FrameReader;
using protocol::FrameWriter;
using protocol::Kind;
using protocol::Op;

// How long the child reads the page for the next request before it sleeps:
// the calls of one motion solve come within microseconds of each other
const int spinMicroseconds = 200;
// How long it sleeps before it looks whether the parent closed the socket
const int sliceMilliseconds = 100;

// Moves the socket to a high descriptor, close-on-exec: below the limit
// of open files (RLIMIT_NOFILE), above the descriptors programs close or
// write to by number (0 to 63 in loops that close "all" of them, 3 as the
// first one opened), and not inherited by a program the FMU runs.
int moveSocketHigh()
{
    rlimit limit {};
    getrlimit(RLIMIT_NOFILE, &limit);
    const rlim_t below = std::min<rlim_t>(limit.rlim_cur, 1024);
    const int high = fcntl(protocol::socketFd, F_DUPFD_CLOEXEC,
                           below > 128 ? int(below) - 64 : 10);
    ::close(protocol::socketFd);
    return high;
}

// Closes every file descriptor above the page's that the parent left open
// without close-on-exec: the child holds nothing of the parent's.
void closeInherited()
{
    std::vector<int> open;
    if (DIR* d = opendir("/proc/self/fd")) {
        while (const dirent* e = readdir(d)) {
            const int fd = std::atoi(e->d_name);
            if (fd > protocol::pageFd && fd != dirfd(d))
                open.push_back(fd);
        }
        closedir(d);
    }
    for (const int fd : open)
        ::close(fd);
}

class Worker {
public:
    Worker(protocol::CallPage& page, int socket) : page_(page), socket_(socket)
    {
    }

    // Serves requests until the end; the exit status.
    int run()
    {
        std::uint32_t seen = 0;
        for (;;) {
            if (!protocol::awaitPost(page_.request, seen, spinMicroseconds,
                                     sliceMilliseconds)) {
                if (parentClosed())
                    return 0;
                continue;
            }
            ++seen;
            if (!receive())
                return 0;
            bool freed = false;
            std::uint64_t seq = 0;
            FrameReader frame(nullptr, nullptr);
            while (inbox_.next(frame, seq))
                freed = serve(frame, seq) || freed;
            if (freed)
                return 0;
        }
    }

private:
    // Takes the posted requests into the inbox: from the page, or from the
    // socket when they were too long for it; false if the parent is gone
    // or said so (an empty message).
    bool receive()
    {
        const protocol::Mailbox& box = page_.request;
        if (box.length == 0)
            return false;
        if (!box.onSocket) {
            inbox_.append(box.body, box.length);
            return true;
        }
        std::size_t in = inbox_.pending();
        while (in < box.length) {
            const long n = inbox_.fill(socket_);
            if (n <= 0)
                return false;
            in += static_cast<std::size_t>(n);
        }
        return true;
    }

    // Whether the parent closed its end of the socket (looked at once a
    // slice). An FMU that closed this end (POLLNVAL) is the parent's to
    // name: it finds the end of the socket after the call.
    bool parentClosed() const
    {
        pollfd p {socket_, POLLIN, 0};
        return ::poll(&p, 1, 0) > 0 && (p.revents & POLLHUP);
    }

    // Runs one request; whether it freed the instance
    bool serve(FrameReader& frame, std::uint64_t seq)
    {
        const Op op = frame.get<Op>();
        const bool reply = frame.get<std::uint8_t>() != 0;
        if (seq != seq_ + 1 && failed_.empty())
            failed_ = "fmuImportWorker: request " + std::to_string(seq)
                + " came after request " + std::to_string(seq_)
                + ": the call page was overwritten";
        seq_ = seq;
        if (!failed_.empty()) {
            // After a failed request without reply, nothing runs until
            // the parent hears of it
            if (reply) {
                postError(failed_);
                failed_.clear();
            }
            return false;
        }
        out_.clear();
        FrameWriter w(out_, seq);
        w.put(Kind::reply).put(std::uint8_t(1));
        std::string error;
        page_.started.store(seq);
        try {
            run(op, frame, w);
        } catch (const std::exception& e) {
            error = e.what();
        }
        page_.finished.store(seq);
        if (!error.empty()) {
            if (reply)
                postError(error);
            else
                failed_ = error;
        } else if (reply) {
            w.finish();
            postReply();
        }
        return op == Op::freeInstance;
    }

    // The results go after the FMU's last message: run writes the
    // message first.
    void run(Op op, FrameReader& in, FrameWriter& out)
    {
        if (op == Op::load) {
            const std::string directory = in.getString();
            const std::string fmuPath = in.getString();
            fmu_.emplace(Fmu::Impl::openUnpacked(directory, fmuPath));
            out.put(std::string());
            return;
        }
        if (op == Op::instantiate) {
            const std::string name = in.getString();
            const bool loggingOn = in.get<std::uint8_t>() != 0;
            instance_ = std::make_unique<Instance>(
                *fmu_, name,
                [this](const std::string& instance, int status,
                       const std::string& category,
                       const std::string& message) {
                    log(instance, status, category, message);
                },
                loggingOn);
            out.put(std::string());
            return;
        }
        Instance& i = *instance_;
        // A get's reply: the instance's last message, then the values
        const auto reply
            = [&](const auto& values) { out.put(i.lastMessage()).put(values); };
        switch (op) {
        case Op::setupExperiment: {
            const double start = in.get<double>();
            const bool stopDefined = in.get<std::uint8_t>() != 0;
            i.setupExperiment(start, stopDefined, in.get<double>());
            break;
        }
        case Op::enterInitializationMode:
            i.enterInitializationMode();
            break;
        case Op::exitInitializationMode:
            i.exitInitializationMode();
            break;
        case Op::terminate:
            i.terminate();
            break;
        case Op::reset:
            i.reset();
            break;
        case Op::setReal: {
            const auto vrs = in.getVector<unsigned int>();
            i.setReal(vrs, in.getVector<double>());
            break;
        }
        case Op::setInteger: {
            const auto vrs = in.getVector<unsigned int>();
            i.setInteger(vrs, in.getVector<int>());
            break;
        }
        case Op::setBoolean: {
            const auto vrs = in.getVector<unsigned int>();
            i.setBoolean(vrs, in.getBools());
            break;
        }
        case Op::setString: {
            const auto vrs = in.getVector<unsigned int>();
            i.setString(vrs, in.getStrings());
            break;
        }
        case Op::getReal:
            return reply(i.getReal(in.getVector<unsigned int>()));
        case Op::getInteger:
            return reply(i.getInteger(in.getVector<unsigned int>()));
        case Op::getBoolean:
            return reply(i.getBoolean(in.getVector<unsigned int>()));
        case Op::getString:
            return reply(i.getString(in.getVector<unsigned int>()));
        case Op::doStep: {
            const double t = in.get<double>(), h = in.get<double>();
            const bool noSet = in.get<std::uint8_t>() != 0;
            const bool mayDiscard = in.get<std::uint8_t>() != 0;
            const auto readAfter = in.getVector<unsigned int>();
            Instance::StepResult result = Instance::StepResult::completed;
            if (mayDiscard)
                result = i.tryDoStep(t, h, noSet);
            else
                i.doStep(t, h, noSet);
            out.put(i.lastMessage()).put(static_cast<std::uint8_t>(result));
            readAfterStep(i, result, readAfter, out);
            return;
        }
        case Op::lastSuccessfulTime: {
            const double t = i.lastSuccessfulTime();
            out.put(i.lastMessage()).put(t);
            return;
        }
        case Op::getState:
            states_[in.get<std::uint64_t>()] = i.getState();
            break;
        case Op::setState:
            i.setState(state(in.get<std::uint64_t>()));
            break;
        case Op::freeState:
            states_.erase(in.get<std::uint64_t>());
            break;
        case Op::serializeState: {
            const auto bytes = i.serializeState(state(in.get<std::uint64_t>()));
            out.put(i.lastMessage()).put(bytes);
            return;
        }
        case Op::deserializeState: {
            const std::uint64_t id = in.get<std::uint64_t>();
            states_[id] = i.deserializeState(in.getVector<char>());
            break;
        }
        case Op::freeInstance:
            states_.clear();
            instance_.reset();
            out.put(std::string());
            return;
        case Op::load:
        case Op::instantiate:
            break;
        }
        out.put(i.lastMessage());
    }

    // The read that follows a completed step (Protocol.hpp): a flag, then
    // the values and the FMU's last message
    void readAfterStep(Instance& i, Instance::StepResult result,
                       const std::vector<unsigned int>& vrs, FrameWriter& out)
    {
        std::vector<double> values;
        bool read = false;
        if (result == Instance::StepResult::completed && !vrs.empty()) {
            page_.reading.store(1);
            try {
                values = i.getReal(vrs);
                read = true;
            } catch (const std::exception&) {
                // asked again, as a call of its own
            }
            page_.reading.store(0);
        }
        out.put(std::uint8_t(read));
        if (read)
            out.put(values).put(i.lastMessage());
    }

    const Instance::State& state(std::uint64_t id) const
    {
        const auto found = states_.find(id);
        if (found == states_.end())
            throw Error("fmuImportWorker: no FMU state " + std::to_string(id));
        return found->second;
    }

    void postError(const std::string& error)
    {
        out_.clear();
        FrameWriter w(out_, seq_);
        w.put(Kind::reply)
            .put(std::uint8_t(0))
            .put(error)
            .put(instance_ ? instance_->lastMessage() : std::string());
        w.finish();
        postReply();
    }

    // Posts the reply in out_: in the page, or, when it is too long for
    // it, its length there and the reply on the socket
    void postReply()
    {
        protocol::Mailbox& box = page_.reply;
        box.length = out_.size();
        box.onSocket = out_.size() > protocol::Mailbox::capacity;
        if (!box.onSocket)
            std::memcpy(box.body, out_.data(), out_.size());
        protocol::post(box);
        if (box.onSocket)
            send(out_);
    }

    void log(const std::string& instance, int status,
             const std::string& category, const std::string& message)
    {
        std::vector<char> buffer;
        FrameWriter w(buffer, seq_);
        w.put(Kind::log)
            .put(std::int32_t(status))
            .put(instance)
            .put(category)
            .put(message);
        w.finish();
        send(buffer);
    }

    // Writes all of buffer to the socket. When that fails, the FMU closed
    // it, or the parent is gone: the parent finds the end of the socket, or
    // this process ends with it (PR_SET_PDEATHSIG).
    void send(const std::vector<char>& buffer)
    {
        std::size_t done = 0;
        while (done < buffer.size()) {
            const ssize_t n = ::send(socket_, buffer.data() + done,
                                     buffer.size() - done, MSG_NOSIGNAL);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                return;
            done += static_cast<std::size_t>(n);
        }
    }

    protocol::CallPage& page_;
    const int socket_;
    std::uint64_t seq_ = 0; // of the request in progress
    protocol::Inbox inbox_;
    std::vector<char> out_;
    std::string failed_; // the error of a failed request without reply
    std::optional<Fmu> fmu_;
    std::unique_ptr<Instance> instance_;
    std::map<std::uint64_t, Instance::State> states_;
};

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "fmuImportWorker runs an FMU for fmuImport "
                     "(Isolation::process); it is not run by hand\n";
        return 2;
    }
    // Ends with the parent, even when the parent is killed (SIGKILL)
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != static_cast<pid_t>(std::atol(argv[1])))
        return 0;
    for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE})
        signal(s, SIG_IGN);
    closeInherited();

    void* page = mmap(nullptr, sizeof(protocol::CallPage),
                      PROT_READ | PROT_WRITE, MAP_SHARED, protocol::pageFd, 0);
    if (page == MAP_FAILED) {
        std::cerr << "fmuImportWorker: cannot map the call page: "
                  << std::strerror(errno) << '\n';
        return 70;
    }
    ::close(protocol::pageFd);
    const int socket = moveSocketHigh();
    if (socket < 0) {
        std::cerr << "fmuImportWorker: cannot move its socket: "
                  << std::strerror(errno) << '\n';
        return 70;
    }
    Worker worker(*static_cast<protocol::CallPage*>(page), socket);
    return worker.run();
}

// fmuImportWorker: runs one instance of an FMU for another process
// (fmuImport's Isolation::process; ChildInstance.hpp starts it): the
// process and the transport of requests; Requests.hpp runs them.
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
#include "Protocol.hpp"
#include "Requests.hpp"

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

namespace {

using namespace fmuImport;
using protocol::FrameReader;
using protocol::FrameWriter;
using protocol::Kind;
using protocol::Op;
using worker::Requests;

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
    Worker(protocol::CallPage& page, int socket)
        : page_(page), socket_(socket),
          requests_(page.reading,
                    [this](const std::string& instance, int status,
                           const std::string& category,
                           const std::string& message) {
                        log(instance, status, category, message);
                    })
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
            requests_.run(op, frame, w);
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

    void postError(const std::string& error)
    {
        out_.clear();
        FrameWriter w(out_, seq_);
        w.put(Kind::reply)
            .put(std::uint8_t(0))
            .put(error)
            .put(requests_.lastMessage());
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
    Requests requests_;
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

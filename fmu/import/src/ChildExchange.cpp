// One exchange of ChildInstance with its child: the queue of requests
// posted in the shared page (Channel.hpp), the reply awaited there, and the
// socket read for the FMU's log messages and for anything else on it.
//
// The socket is read without waiting after every reply: one system call,
// which finds at once the bytes an FMU wrote to it and the end of a socket
// that an FMU closed, in the call that did it.
#include "ChildInstance.hpp"

#include "CallReport.hpp"
#include "LocalInstance.hpp"

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>

namespace fmuImport {

using protocol::FrameReader;
using protocol::Kind;
using protocol::Mailbox;

namespace {

// How long the parent reads the page for a reply before it sleeps: a fast
// FMU's reply then costs no sleep and wake-up of the parent
const int spinMicroseconds = 50;
// How long it sleeps before it looks at the socket: how soon it notices
// the death of a child in a call
const int sliceMilliseconds = 10;

} // namespace

void ChildInstance::postQueue()
{
    Mailbox& box = page_->request;
    box.length = queue_.size();
    box.onSocket = queue_.size() > Mailbox::capacity;
    if (!box.onSocket)
        std::memcpy(box.body, queue_.data(), queue_.size());
    protocol::post(box);
    for (std::size_t done = 0; box.onSocket && done < queue_.size();) {
        const ssize_t n = ::send(socket_, queue_.data() + done,
                                 queue_.size() - done, MSG_NOSIGNAL);
        if (n > 0)
            done += static_cast<std::size_t>(n);
        else if (n < 0 && errno == EAGAIN) {
            // The child reads the queue as it runs the requests
            pollfd p {socket_, POLLOUT, 0};
            const int timeoutMs = timeout_ > 0
                ? static_cast<int>(std::ceil(timeout_ * 1000))
                : -1;
            if (::poll(&p, 1, timeoutMs) == 0)
                lose(Fault::timedOut);
        } else if (!(n < 0 && errno == EINTR))
            lose(Fault::ended);
    }
    queue_.clear();
}

void ChildInstance::awaitReply(std::uint32_t seen)
{
    // The limit is per call: while the child moves on to its next request,
    // the clock starts again.
    using Clock = std::chrono::steady_clock;
    const auto limit = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(timeout_ > 0 ? timeout_ : 0));
    std::uint64_t progress = page_->started.load() + page_->finished.load();
    Clock::time_point deadline = Clock::now() + limit;
    while (!protocol::awaitPost(page_->reply, seen, spinMicroseconds,
                                sliceMilliseconds)) {
        readSocket(false, false);
        if (!(timeout_ > 0))
            continue;
        const std::uint64_t now
            = page_->started.load() + page_->finished.load();
        if (now != progress) {
            progress = now;
            deadline = Clock::now() + limit;
        } else if (Clock::now() >= deadline)
            lose(Fault::timedOut);
    }
}

void ChildInstance::readSocket(bool wait, bool afterPost)
{
    for (;;) {
        const long n = inbox_.fill(socket_);
        if (n > 0 && !wait)
            continue;
        if (n > 0)
            return;
        if (n == 0) {
            if (inbox_.pending())
                lose(Fault::garbled, afterPost, inbox_.cutShort().what());
            lose(afterPost ? Fault::closedChannel : Fault::ended, afterPost);
        }
        if (errno != EAGAIN)
            lose(Fault::ended, afterPost);
        if (!wait)
            return;
        pollfd p {socket_, POLLIN, 0};
        const int timeoutMs
            = timeout_ > 0 ? static_cast<int>(std::ceil(timeout_ * 1000)) : -1;
        if (::poll(&p, 1, timeoutMs) == 0)
            lose(Fault::timedOut, afterPost);
    }
}

bool ChildInstance::nextFrame(FrameReader& frame, std::uint64_t& seq,
                              bool afterPost)
{
    try {
        return inbox_.next(frame, seq);
    } catch (const protocol::Garbled& e) {
        lose(Fault::garbled, afterPost, e.what());
    }
}

FrameReader ChildInstance::exchange()
{
    const std::uint32_t seen = page_->reply.posted.load();
    postQueue();
    awaitReply(seen);
    // The log messages before the reply, and what else the socket holds
    readSocket(false, true);
    const Mailbox& box = page_->reply;
    FrameReader frame(nullptr, nullptr);
    std::uint64_t seq = 0;
    for (;;) {
        while (nextFrame(frame, seq, true)) {
            if (frame.get<Kind>() == Kind::reply)
                return reply(frame, seq);
            log(frame);
        }
        if (box.onSocket) {
            readSocket(true, true);
            continue;
        }
        // The child sends whole frames, and all of them before its post
        if (inbox_.pending())
            lose(Fault::garbled, true,
                 "carried stray bytes (" + std::to_string(inbox_.pending())
                     + " bytes that are not a message)");
        inbox_.append(box.body, box.length);
        if (!nextFrame(frame, seq, true) || frame.get<Kind>() != Kind::reply)
            lose(Fault::garbled, true,
                 "carried an incomplete reply (" + std::to_string(box.length)
                     + " bytes in the call page)");
        return reply(frame, seq);
    }
}

void ChildInstance::log(FrameReader& frame)
{
    const int status = frame.get<std::int32_t>();
    const std::string instance = frame.getString();
    const std::string category = frame.getString();
    const std::string message = frame.getString();
    if (logger_)
        logger_(instance, status, category, message);
    else
        logToStderr(instance, status, category, message,
                    fmu->description.fmiMajorVersion == 3);
}

FrameReader ChildInstance::reply(FrameReader& frame, std::uint64_t seq)
{
    if (seq != seq_ || inbox_.pending())
        lose(Fault::garbled, true,
             "carried a message out of sequence (a reply to request "
                 + std::to_string(seq) + " where request "
                 + std::to_string(seq_) + "'s was due"
                 + (inbox_.pending() ? ", and bytes after it)" : ")"));
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

} // namespace fmuImport

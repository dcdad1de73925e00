// The page of shared memory between an instance in this process
// (ChildInstance) and its child process (fmuImportWorker): a mailbox for
// each direction, which carries the frames of a call (Protocol.hpp), and
// the marks of the request the child is running.
//
// A call through a socket costs a system call on each side and, when the
// other side sleeps in it, a wake-up: about 40 us per round trip on an idle
// machine. Through the page, a reader that is already waiting (spinning a
// few tens of microseconds) sees the message as soon as it is posted; only
// then does it sleep, in a futex wait on the mailbox's counter, which the
// poster wakes only when the reader says it sleeps. The futex wait has a
// time limit (a slice), so that the parent notices a child that died, and
// the child a parent that closed the socket, at the end of a slice at the
// latest: a death does not wake a futex.
#ifndef FMUIMPORT_CHANNEL_HPP
#define FMUIMPORT_CHANNEL_HPP

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace fmuImport {
namespace protocol {

// The child's file descriptors at its start: the socket and the page. The
// child moves the socket to a high, close-on-exec descriptor and closes
// both (fmuImportWorker.cpp), so that an FMU that writes to or closes
// descriptors by number does not reach them.
constexpr int socketFd = 3;
constexpr int pageFd = 4;

// Messages of one direction
struct Mailbox {
    // The longest message posted in the page; a longer one is sent on the
    // socket, and the page says only its length
    static constexpr std::size_t capacity = 65536;

    // The number of messages posted, modulo 2^32: the futex word
    std::atomic<std::uint32_t> posted {0};
    // The reader sleeps on posted, or is about to
    std::atomic<std::uint32_t> sleeping {0};
    // Bytes of the last message's frames, in body or on the socket
    std::uint64_t length = 0;
    std::uint32_t onSocket = 0;
    char body[capacity];
};

// The request the child runs: started is its sequence number, set before
// the request runs; finished is set to it afterwards. A request is in
// progress while started > finished. While reading is set, the request in
// progress is a step's read of the outputs (Protocol.hpp).
struct CallPage {
    Mailbox request;
    Mailbox reply;
    std::atomic<std::uint64_t> started {0};
    std::atomic<std::uint64_t> finished {0};
    std::atomic<std::uint32_t> reading {0};
};
static_assert(std::atomic<std::uint64_t>::is_always_lock_free
                  && std::atomic<std::uint32_t>::is_always_lock_free,
              "the page is shared between processes");

// Posts the message the poster wrote in box (body or socket, length,
// onSocket) and wakes its reader if it sleeps.
void post(Mailbox& box);

// Waits until box holds a message after the seen'th: true as soon as it
// does, false after about sliceMilliseconds without one. It first reads
// the counter for spinMicroseconds, yielding the processor between reads
// (sched_yield): on a machine with more processes than cores the poster
// can then run, where a busy loop took its time and made a call ten times
// slower. Then it sleeps in a futex wait.
bool awaitPost(Mailbox& box, std::uint32_t seen, int spinMicroseconds,
               int sliceMilliseconds);

} // namespace protocol
} // namespace fmuImport

#endif

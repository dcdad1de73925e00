#include "Channel.hpp"

#include <linux/futex.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <chrono>
#include <ctime>

namespace fmuImport {
namespace protocol {

namespace {

// glibc has no wrapper for futex. Not FUTEX_PRIVATE_FLAG: the word is in
// memory shared by two processes.
long futex(std::atomic<std::uint32_t>& word, int op, std::uint32_t value,
           const timespec* timeout)
{
    static_assert(sizeof word == sizeof(std::uint32_t), "a futex word");
    return syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word), op,
                   value, timeout, nullptr, 0);
}

} // namespace

void post(Mailbox& box)
{
    // Both sequentially consistent, as in awaitPost: either the reader sees
    // the new count before it sleeps, or this sees that it sleeps.
    box.posted.fetch_add(1);
    if (box.sleeping.load())
        futex(box.posted, FUTEX_WAKE, 1, nullptr);
}

bool awaitPost(Mailbox& box, std::uint32_t seen, int spinMicroseconds,
               int sliceMilliseconds)
{
    using Clock = std::chrono::steady_clock;
    const Clock::time_point spinUntil
        = Clock::now() + std::chrono::microseconds(spinMicroseconds);
    while (box.posted.load(std::memory_order_acquire) == seen) {
        if (Clock::now() > spinUntil) {
            box.sleeping.store(1);
            if (box.posted.load() == seen) {
                const timespec slice {sliceMilliseconds / 1000,
                                      sliceMilliseconds % 1000 * 1000000L};
                // Returns at a post, a signal, the slice's end, or at once
                // when the count moved on since it was read (EAGAIN)
                futex(box.posted, FUTEX_WAIT, seen, &slice);
            }
            box.sleeping.store(0);
            return box.posted.load(std::memory_order_acquire) != seen;
        }
        sched_yield();
    }
    return true;
}

} // namespace protocol
} // namespace fmuImport

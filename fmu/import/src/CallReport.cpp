#include "CallReport.hpp"

#include "UnpackRegistry.hpp"
#include "fmuImport/fmuImport.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>
#include <thread>

namespace fmuImport {

namespace {

// The call in progress. Process-wide because a signal handler reads it;
// constant-initialised, so usable before main and from any thread.
struct CurrentCall {
    std::atomic<std::uint64_t> count {
        0}; // calls begun plus calls ended: odd while a call is in progress
    std::atomic<const CallSite*> site {nullptr};
    std::atomic<const char*> function {nullptr};
    std::atomic<double> time {0.0};
};

CurrentCall current;

// The words of reports (setReports), in fixed buffers that a signal
// handler can read. Written before the first FMU is loaded.
struct Words {
    char prefix[256] = "";
    char timeoutSource[256] = "";
    std::atomic<int> timeoutStatus {1};
    std::atomic<int> exitStatus {1};
};

Words words;

void copyWords(char (&to)[256], const std::string& from)
{
    const std::size_t n = std::min(from.size(), sizeof to - 1);
    std::memcpy(to, from.data(), n);
    to[n] = '\0';
}

bool marked(std::uint64_t count)
{
    return count % 2 == 1;
}

// One call more begun or ended. Calls come from one thread at a time, and
// the logger callback inside a call on the same thread: the count has one
// writer, and a load and a store do what fetch_add did, without its locked
// instruction. The watchdog thread and the signal handler only read it.
void advanceCount()
{
    current.count.store(current.count.load(std::memory_order_relaxed) + 1,
                        std::memory_order_release);
}

// The call in progress: its function, time and site, or false when no
// call is marked. Async-signal-safe.
struct MarkedCallText {
    const CallSite* site = nullptr;
    const char* function = nullptr;
    double time = 0;

    bool read() noexcept
    {
        const std::uint64_t count
            = current.count.load(std::memory_order_acquire);
        site = current.site.load(std::memory_order_relaxed);
        function = current.function.load(std::memory_order_relaxed);
        time = current.time.load(std::memory_order_relaxed);
        return marked(count) && site && function;
    }

    // "fmi2DoStep at t = 0.75 in FMU 'x.fmu', instance 'x'"
    void describe(SignalSafeText& text) const noexcept
    {
        describeCall(text, function, time, site->text.c_str());
    }
};

// Flushes standard output if no other thread holds it (the FMU may hang in
// printf): the host's log before the report. Not async-signal-safe: for
// the watchdog thread and the exit hook only.
void flushOutput()
{
    if (ftrylockfile(stdout) == 0) {
        fflush_unlocked(stdout);
        funlockfile(stdout);
    }
}

[[noreturn]] void timeOut(const CallSite& site, const char* function,
                          double time)
{
    SignalSafeText text;
    text << words.prefix << "time-out: ";
    describeCall(text, function, time, site.text.c_str());
    text << " did not return within ";
    text.number(site.timeout) << " s" << words.timeoutSource << "\n";
    flushOutput();
    text.writeToStderr();
    // The FMU is still running in the main thread: no destructor will
    // remove its unpacked copy (the mapped binary stays mapped).
    processEnds();
    ::_exit(words.timeoutStatus.load());
}

// The host's function for a process that ends without its exit handlers
// (setEndingHook)
std::atomic<void (*)()> endingHook {nullptr};

// The polling period [s]: an eighth of the shortest time limit, within
// 1 ms and 0.1 s.
std::atomic<double> period {0.1};

// Polls the call counter: a call still in progress, with the same count,
// its site's time limit after it was first seen has taken at least that
// long. It is reported at most two polling periods late; calls cost
// nothing but the counter updates.
void watch()
{
    using Clock = std::chrono::steady_clock;
    std::uint64_t seen = 0;
    Clock::time_point since;
    for (;;) {
        std::this_thread::sleep_for(
            std::chrono::duration<double>(period.load()));
        const std::uint64_t count
            = current.count.load(std::memory_order_acquire);
        if (!marked(count))
            continue;
        const Clock::time_point now = Clock::now();
        if (count != seen) {
            seen = count;
            since = now;
            continue;
        }
        const CallSite* site = current.site.load(std::memory_order_relaxed);
        const char* function = current.function.load(std::memory_order_relaxed);
        const double time = current.time.load(std::memory_order_relaxed);
        if (!site || !function || !(site->timeout > 0)
            || now - since < std::chrono::duration<double>(site->timeout)
            || current.count.load(std::memory_order_acquire) != count)
            continue;
        timeOut(*site, function, time);
    }
}

// exit() while a call is marked: the FMU called it (the logger callback,
// the host's code, lifts the mark). Names the call and ends the process
// with a non-zero status: the FMU's own, or the host's (setReports), in
// place of 0. The exit handlers registered after this one (at or after the
// first FMU load: the removal of the unpacked files, the host's) have run;
// standard output is flushed here, since _exit skips the rest.
extern "C" void onExit(int status, void*)
{
    MarkedCallText call;
    if (!call.read())
        return;
    SignalSafeText text;
    text << words.prefix << "the FMU exited (status " << long(status)
         << ") in ";
    call.describe(text);
    text << "\n";
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    text.writeToStderr();
    ::_exit(status != 0 ? status : words.exitStatus.load());
}

} // namespace

void setReports(const Reports& reports)
{
    copyWords(words.prefix, reports.prefix);
    copyWords(words.timeoutSource, reports.timeoutSource);
    words.timeoutStatus = reports.timeoutStatus;
    words.exitStatus = reports.exitStatus;
}

void setEndingHook(void (*hook)())
{
    endingHook.store(hook);
}

void processEnds() noexcept
{
    if (void (*hook)() = endingHook.load())
        hook();
    UnpackRegistry::removeAll();
}

const char* reportPrefix() noexcept
{
    return words.prefix;
}

const char* timeoutSource() noexcept
{
    return words.timeoutSource;
}

std::string siteText(const std::string& fmuPath, const std::string& name,
                     const std::string& owner)
{
    return " in FMU '" + fmuPath + "'"
        + (owner.empty() ? ", instance '" + name + "'" : " of " + owner);
}

MarkedCall::MarkedCall(const CallSite& site, const char* function, double time)
{
    current.site.store(&site, std::memory_order_relaxed);
    current.function.store(function, std::memory_order_relaxed);
    current.time.store(time, std::memory_order_relaxed);
    advanceCount();
}

MarkedCall::~MarkedCall()
{
    advanceCount();
}

UnmarkedCallback::UnmarkedCallback()
    : wasMarked_(marked(current.count.load(std::memory_order_relaxed)))
{
    if (wasMarked_)
        advanceCount();
}

UnmarkedCallback::~UnmarkedCallback()
{
    if (wasMarked_)
        advanceCount();
}

void watchCalls(double timeout)
{
    if (!(timeout > 0))
        return;
    static std::mutex mutex;
    const std::lock_guard<std::mutex> lock(mutex);
    const double wanted = std::clamp(timeout / 8, 1e-3, 0.1);
    if (wanted < period.load())
        period = wanted;
    static bool started = false;
    if (!started) {
        std::thread(watch).detach();
        started = true;
    }
}

void reportCrash(int signal) noexcept
{
    MarkedCallText call;
    if (!call.read())
        return;
    SignalSafeText text;
    text << words.prefix << "the FMU crashed (";
    describeSignal(text, signal);
    text << ") in ";
    call.describe(text);
    text << "\n";
    text.writeToStderr();
}

void installExitReport()
{
    on_exit(onExit, nullptr);
}

SignalSafeText& SignalSafeText::operator<<(const char* text) noexcept
{
    while (text && *text && size_ + 1 < sizeof buffer_)
        buffer_[size_++] = *text++;
    buffer_[size_] = '\0';
    return *this;
}

SignalSafeText& SignalSafeText::operator<<(long number) noexcept
{
    char digits[32];
    const std::to_chars_result r
        = std::to_chars(digits, digits + sizeof digits - 1, number);
    *r.ptr = '\0';
    return *this << digits;
}

SignalSafeText& SignalSafeText::number(double value) noexcept
{
    if (std::isnan(value))
        return *this << "nan";
    char digits[64];
    const std::to_chars_result r
        = std::to_chars(digits, digits + sizeof digits - 1, value);
    *r.ptr = '\0';
    return *this << digits;
}

void SignalSafeText::writeToStderr() const noexcept
{
    const char* p = buffer_;
    std::size_t left = size_;
    while (left > 0) {
        const ssize_t n = ::write(STDERR_FILENO, p, left);
        if (n <= 0)
            return;
        p += n;
        left -= static_cast<std::size_t>(n);
    }
}

void describeCall(SignalSafeText& text, const char* function, double time,
                  const char* site) noexcept
{
    text << function;
    if (!std::isnan(time)) {
        text << " at t = ";
        text.number(time);
    }
    text << site;
}

void describeSignal(SignalSafeText& text, int signal) noexcept
{
    switch (signal) {
    case SIGSEGV:
        text << "SIGSEGV, segmentation fault";
        return;
    case SIGBUS:
        text << "SIGBUS, bus error";
        return;
    case SIGFPE:
        text << "SIGFPE, arithmetic exception";
        return;
    case SIGILL:
        text << "SIGILL, illegal instruction";
        return;
    case SIGABRT:
        text << "SIGABRT, abort";
        return;
    case SIGKILL:
        text << "SIGKILL, killed";
        return;
    default:
        text << "signal " << long(signal);
    }
}

} // namespace fmuImport

#include "Watchdog.hpp"

#include "Csv.hpp"
#include "Errors.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

namespace fmusim {

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

// Writes text to standard error with write(2) only: usable in a signal
// handler and while another thread holds std::cerr.
void writeError(const char* text)
{
    std::size_t left = std::strlen(text);
    while (left > 0) {
        const ssize_t n = ::write(STDERR_FILENO, text, left);
        if (n <= 0)
            return;
        text += n;
        left -= static_cast<std::size_t>(n);
    }
}

// "fmi2DoStep at t = 0.5 in FMU 'x.fmu', instance 'x'". snprintf is not on
// POSIX's list of async-signal-safe functions, but glibc's formats %s and
// %.17g into the caller's buffer without allocating, and the crash handler
// runs once, on the way out.
void describeCall(char* buffer, std::size_t size, const CallSite& site,
                  const char* function, double time)
{
    if (std::isnan(time))
        std::snprintf(buffer, size, "%s in FMU '%s', instance '%s'", function,
                      site.fmuPath.c_str(), site.instanceName.c_str());
    else
        std::snprintf(buffer, size,
                      "%s at t = %.17g in FMU '%s', instance '%s'", function,
                      time, site.fmuPath.c_str(), site.instanceName.c_str());
}

[[noreturn]] void timeOut(const CallSite& site, const char* function,
                          double time, double seconds)
{
    char call[2048], message[2304];
    describeCall(call, sizeof call, site, function, time);
    std::snprintf(
        message, sizeof message,
        "fmusim: time-out: %s did not return within %s s (--timeout)\n", call,
        formatNumber(seconds).c_str());
    writeError(message);
    // The FMU is still running in the main thread: no destructor will remove
    // its unpacked copy, so remove it here (the mapped binary stays mapped).
    std::error_code ignored;
    std::filesystem::remove_all(site.unpackDirectory, ignored);
    // Rows are written through (CsvWriter), so nothing is left to flush.
    ::_exit(exitTimeout);
}

// Polls the call counter: a call still in progress, with the same count,
// `seconds` after it was first seen has taken at least that long. It is
// reported at most two polling periods late; calls cost nothing but the
// counter updates.
void watch(double seconds)
{
    using Clock = std::chrono::steady_clock;
    const std::chrono::duration<double> limit(seconds),
        period(std::clamp(seconds / 8, 1e-3, 0.1));
    std::uint64_t seen = 0;
    Clock::time_point since;
    for (;;) {
        std::this_thread::sleep_for(period);
        const std::uint64_t count
            = current.count.load(std::memory_order_acquire);
        if (count % 2 == 0)
            continue;
        const Clock::time_point now = Clock::now();
        if (count != seen) {
            seen = count;
            since = now;
            continue;
        }
        if (now - since < limit)
            continue;
        const CallSite* site = current.site.load(std::memory_order_relaxed);
        const char* function = current.function.load(std::memory_order_relaxed);
        const double time = current.time.load(std::memory_order_relaxed);
        if (current.count.load(std::memory_order_acquire) != count || !site
            || !function)
            continue;
        timeOut(*site, function, time, seconds);
    }
}

const char* signalName(int signal)
{
    switch (signal) {
    case SIGSEGV:
        return "SIGSEGV, segmentation fault";
    case SIGBUS:
        return "SIGBUS, bus error";
    case SIGFPE:
        return "SIGFPE, arithmetic exception";
    case SIGILL:
        return "SIGILL, illegal instruction";
    case SIGABRT:
        return "SIGABRT, abort";
    default:
        return "a fatal signal";
    }
}

// Names the call in progress, then restores the default action and raises
// the signal again: blocked while a handler runs, it is delivered when the
// handlers return and ends the process, so the exit status still says
// which signal it was. fmuImport's handlers, installed when the first FMU
// is unpacked and so after this one, remove the unpacked FMUs and then
// call this one.
void crashed(int signal)
{
    char call[2048], message[2304];
    const std::uint64_t count = current.count.load(std::memory_order_acquire);
    const CallSite* site = current.site.load(std::memory_order_relaxed);
    const char* function = current.function.load(std::memory_order_relaxed);
    if (count % 2 == 1 && site && function) {
        describeCall(call, sizeof call, *site, function,
                     current.time.load(std::memory_order_relaxed));
        std::snprintf(message, sizeof message,
                      "fmusim: the FMU crashed (%s) in %s\n",
                      signalName(signal), call);
    } else {
        std::snprintf(message, sizeof message,
                      "fmusim: crashed (%s) outside any FMU call\n",
                      signalName(signal));
    }
    writeError(message);
    struct sigaction fallback { };
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    ::sigaction(signal, &fallback, nullptr);
    ::raise(signal);
}

} // namespace

void startWatchdog(double seconds)
{
    if (!(seconds > 0))
        return;
    std::thread(watch, seconds).detach();
}

void installCrashReport()
{
    // Its own stack, so that an FMU that overflows the stack is reported too.
    static char alternateStack[64 * 1024];
    stack_t stack {};
    stack.ss_sp = alternateStack;
    stack.ss_size = sizeof alternateStack;
    ::sigaltstack(&stack, nullptr);
    struct sigaction action { };
    action.sa_handler = crashed;
    action.sa_flags = SA_ONSTACK;
    sigemptyset(&action.sa_mask);
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
        ::sigaction(signal, &action, nullptr);
}

FmuCall::FmuCall(const CallSite& site, const char* function, double time)
{
    current.site.store(&site, std::memory_order_relaxed);
    current.function.store(function, std::memory_order_relaxed);
    current.time.store(time, std::memory_order_relaxed);
    current.count.fetch_add(1, std::memory_order_release);
}

FmuCall::~FmuCall()
{
    current.count.fetch_add(1, std::memory_order_release);
}

} // namespace fmusim

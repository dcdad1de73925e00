// Which call into an FMU is in progress in this process, and the reports
// that name it when it does not come back (fmuImport.hpp, Reports):
//
// - MarkedCall marks the call for its length (set before, cleared after);
// - a watchdog thread ends the process when a marked call outlasts its
//   site's time limit, with a report naming the FMU, the instance, the
//   fmi2 function and the time;
// - reportCrash, called by the importer's fatal-signal handler
//   (UnpackRegistry), names the call an FMU crashed in (SIGSEGV, SIGBUS,
//   SIGFPE, SIGILL, SIGABRT) before the signal goes on to the handler that
//   was there before (OpenFOAM's stack trace);
// - an exit hook names the call an FMU called exit() in, and makes the
//   exit status non-zero.
//
// Every report is one line written with write(2) to standard error, built
// in a buffer on the stack without allocating (SignalSafeText). The same
// words make the messages of a child process's lost call (ChildInstance).
// Calls into FMUs come from one thread at a time: there is one mark per
// process.
#ifndef FMUIMPORT_CALLREPORT_HPP
#define FMUIMPORT_CALLREPORT_HPP

#include <cstddef>
#include <string>

namespace fmuImport {

// What a report names besides the function and the time: " in FMU 'x.fmu',
// instance 'x'" (or " in FMU 'x.fmu' of <owner>"), and the time limit of
// the site's calls [s] (0: none). Owned by an instance; it must outlive the
// calls that name it.
struct CallSite {
    std::string text;
    double timeout = 0;
};

// " in FMU '<path>', instance '<name>'", or " in FMU '<path>' of <owner>"
// when owner is not empty.
std::string siteText(const std::string& fmuPath, const std::string& name,
                     const std::string& owner);

// Marks a call from construction to destruction. Cheap: five atomic
// stores and no locked instruction (calls come from one thread at a time),
// no system call. function must be a string literal.
class MarkedCall {
public:
    // time: the communication point (NaN when there is none yet)
    MarkedCall(const CallSite& site, const char* function, double time);
    ~MarkedCall();
    MarkedCall(const MarkedCall&) = delete;
    MarkedCall& operator=(const MarkedCall&) = delete;
};

// Lifts the mark while the host's code runs inside a call (the FMU's
// logger callback): a crash or exit() there is the host's, not the FMU's.
class UnmarkedCallback {
public:
    UnmarkedCallback();
    ~UnmarkedCallback();
    UnmarkedCallback(const UnmarkedCallback&) = delete;
    UnmarkedCallback& operator=(const UnmarkedCallback&) = delete;

private:
    bool wasMarked_;
};

// Starts the watchdog thread (once per process) for a site with a time
// limit, or makes it poll often enough for this limit.
void watchCalls(double timeout);

// Writes the crash report if a call is marked. Async-signal-safe.
void reportCrash(int signal) noexcept;

// The process ends without its exit handlers (a fatal signal, a time-out):
// runs the host's ending hook (setEndingHook), then removes the unpacked
// FMUs. Async-signal-safe when the hook is.
void processEnds() noexcept;

// Installs the exit hook (on_exit). Once, at the first FMU load, before the
// handlers that remove the unpacked files, so that it runs after them.
void installExitReport();

// A line of text in a fixed buffer: async-signal-safe appending, numbers in
// their shortest exact form (std::to_chars), truncated when full.
class SignalSafeText {
public:
    SignalSafeText& operator<<(const char* text) noexcept;
    SignalSafeText& operator<<(long number) noexcept;
    // "0.75", "1e+300", "nan"
    SignalSafeText& number(double value) noexcept;
    const char* c_str() const noexcept { return buffer_; }
    std::size_t size() const noexcept { return size_; }
    void writeToStderr() const noexcept;

private:
    char buffer_[4096] = "";
    std::size_t size_ = 0;
};

// "fmi2DoStep at t = 0.75 in FMU 'x.fmu', instance 'x'" (no time when NaN).
void describeCall(SignalSafeText& text, const char* function, double time,
                  const char* site) noexcept;

// "SIGSEGV, segmentation fault"; "signal 42" for others.
void describeSignal(SignalSafeText& text, int signal) noexcept;

// The process-wide words of reports (fmuImport.hpp, setReports).
const char* reportPrefix() noexcept;
const char* timeoutSource() noexcept;

} // namespace fmuImport

#endif

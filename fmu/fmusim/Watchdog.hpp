// Every call into an FMU is announced here (an FmuCall for the length of
// the call), so that fmusim can say which call never returned or crashed:
//
// - a watchdog thread (startWatchdog) ends the process with exitTimeout
//   when one call outlasts the time-out, with a message naming the FMU, the
//   instance, the fmi2 function and the time;
// - a fatal-signal handler (installCrashReport) names the call an FMU
//   crashed in (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT), then lets the
//   signal end the process as it would have.
//
// Neither flushes output: CsvWriter writes each row through, so the rows
// are on disk before every call.
#ifndef FMUSIM_WATCHDOG_HPP
#define FMUSIM_WATCHDOG_HPP

#include <string>

namespace fmusim {

// What a message about a call names: the FMU file and the instance, and the
// directory the FMU is unpacked in (removed on a time-out).
struct CallSite {
    std::string fmuPath;
    std::string instanceName;
    std::string unpackDirectory;
};

// Starts the watchdog thread; seconds <= 0: no time-out. Once per process.
void startWatchdog(double seconds);

// Installs the fatal-signal handlers. Once per process, before the first
// FMU is loaded (fmuImport then chains its own to them).
void installCrashReport();

// Announces a call from construction to destruction. The site and the
// function name must outlive it; calls do not nest. Cheap: two atomic
// increments and three atomic stores, no system call.
class FmuCall {
public:
    // time: the communication point (NaN when there is none yet)
    FmuCall(const CallSite& site, const char* function, double time);
    ~FmuCall();
    FmuCall(const FmuCall&) = delete;
    FmuCall& operator=(const FmuCall&) = delete;
};

} // namespace fmusim

#endif

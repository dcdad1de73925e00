// fmuImport: what this process reports when an FMU running in it
// crashes, hangs or exits in a call, and the host's hook for a process
// that ends so.
// Part of the importer's public interface (fmuImport.hpp includes every
// part), C++11 like the rest of it.
#ifndef FMUIMPORT_REPORTS_HPP
#define FMUIMPORT_REPORTS_HPP

#include <string>

namespace fmuImport {

// The words and exit statuses of the reports that this process writes when
// an FMU running in it (Isolation::none) crashes, hangs or exits in a call:
// "<prefix>the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep at t
// = 0.75 in FMU 'x.fmu', instance 'x'", "<prefix>time-out: ... did not
// return within 1 s<timeoutSource>", "<prefix>the FMU exited (status 0) in
// ...". Process-wide; set it before the first FMU is loaded.
struct Reports {
    std::string prefix; // "fmusim: "; at most 255 characters, as the next
    std::string timeoutSource; // what set the limit: " (--timeout)"
    int timeoutStatus = 1; // exit status after a time-out
    int exitStatus = 1; // exit status in place of an FMU's exit(0)
};
void setReports(const Reports& reports);

// A function of the host's that the importer calls when the process ends
// without running its exit handlers: from its handlers of fatal signals
// (those named at Fmu: the faults, and SIGINT, SIGTERM, ... when they end
// the process) and before a time-out ends it (Reports). It runs in a signal
// handler or in the watchdog thread while the process may be stopped
// anywhere: it must be async-signal-safe and return soon (the OpenFOAM
// bridge waits there, at most a second, for its writer thread to put the
// rows it holds on disk). One per process: the latest set; nullptr for none.
void setEndingHook(void (*hook)());

} // namespace fmuImport

#endif

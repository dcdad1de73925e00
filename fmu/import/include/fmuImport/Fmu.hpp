// fmuImport: an FMU file unpacked and loaded (Fmu), where its instances run
// (Isolation, FmuOptions), and the SHA-256 of a file.
// Part of the importer's public interface (fmuImport.hpp includes every
// part), C++11 like the rest of it.
#ifndef FMUIMPORT_FMU_HPP
#define FMUIMPORT_FMU_HPP

#include "fmuImport/ModelDescription.hpp"
#include <memory>
#include <string>

namespace fmuImport {

// Where the code of an FMU's instances runs.
enum class Isolation {
    // In this process, the fastest. An FMU that crashes, aborts or calls
    // exit() in a call ends this process, after a report on standard error
    // naming the call (the FMU, the instance, the fmi2 function and the
    // time): the importer's handlers for SIGSEGV, SIGBUS, SIGFPE, SIGILL
    // and SIGABRT write it and then hand the signal to the handler that was
    // there before (the host's: OpenFOAM's stack trace); an exit hook makes
    // the status of an exit(0) non-zero (Reports). A call that outlasts the
    // time limit ends the process too (a watchdog thread).
    none,
    // Each instance in a child process of its own, the helper program
    // fmuImportWorker (started with posix_spawn; found through the
    // environment variable FMUIMPORT_WORKER, beside the running program,
    // in ../bin of the library that holds the importer, in the build tree,
    // or on PATH), driven through a page of shared memory. The FMU's
    // binary is not loaded in this process. A crash, abort() or exit() of
    // the FMU, a call that outlasts the time limit (the child is killed),
    // or an FMU that writes to or closes the channel throws LostCall from
    // the call; this process goes on. A call costs microseconds: calls that
    // return nothing (fmi2Set*, fmi2GetFMUstate, fmi2SetFMUstate,
    // fmi2FreeFMUstate) after initialization go with the next call that
    // returns something, whose Error reports their failure. Not a sandbox:
    // the child runs with this process's rights.
    process
};

// How an Fmu's instances run and how reports name them.
struct FmuOptions {
    Isolation isolation = Isolation::none;
    // The longest one fmi2 call of an instance may take [s]; 0: no limit.
    // Isolation::none: the process ends with a report (Reports); process:
    // the child is killed and the call throws LostCall. Loading the binary
    // (dlopen) is not limited.
    double timeout = 0;
    // How reports of a lost call name the instance's owner, "restraint
    // spring": "... in FMU 'x.fmu' of restraint spring"; empty: "... in
    // FMU 'x.fmu', instance '<name>'".
    std::string owner;
};

// An unpacked and loaded .fmu. Reads and checks modelDescription.xml from
// the archive (fmiVersion 2.0 or 3.0, <CoSimulation>: an FMI 3.0 FMU for
// model exchange or scheduled execution only, or with clocks, is refused
// with an Error that says so), then unpacks it, the binary
// (binaries/linux64/<modelIdentifier>.so for 2.0,
// binaries/x86_64-linux/<modelIdentifier>.so for 3.0) and everything under
// resources/ (nothing else) into a private temporary directory,
// $TMPDIR/fmuImport-<pid>-XXXXXX, loads the binary and resolves the common
// and co-simulation fmi2 (or fmi3) functions (a co-simulation-only FMU need
// not export the model-exchange ones).
//
// Limits: an entry may unpack to at most 256 MiB, all of them together to
// at most 1 GiB, or to the number of bytes in the environment variable
// FMUIMPORT_MAX_UNPACK_BYTES (which also caps an entry). They are checked
// on the sizes the zip directory declares, before anything is written, and
// again on the bytes written.
//
// Fmu objects of one file (the same canonical path, size and modification
// time) made while an earlier one or its instances are alive share one
// unpack directory and one loaded binary.
//
// The directory is removed on failure and when the last Fmu and Instance of
// it are gone (instances keep the binary loaded), and also when the process
// ends by exit() or by SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGSEGV,
// SIGFPE, SIGABRT, SIGBUS or SIGILL (handlers installed at the first load;
// they chain to the handlers installed before or after them). SIGKILL
// leaves it behind: the first load of a process into a temporary folder
// removes there every fmuImport-<pid>-XXXXXX directory of its user whose
// process no longer exists (no /proc/<pid>). Host floating-point traps are masked
// during every call into the FMU. A moved-from Fmu or Instance may only be
// destroyed or assigned to.
class Fmu {
public:
    // With Isolation::process the binary is not loaded here: a missing
    // fmi2 function is reported when the first instance is made.
    explicit Fmu(const std::string& fmuPath,
                 const FmuOptions& options = FmuOptions());
    ~Fmu();
    Fmu(Fmu&&) noexcept;
    Fmu& operator=(Fmu&&) noexcept;
    Fmu(const Fmu&) = delete;
    Fmu& operator=(const Fmu&) = delete;

    const std::string& path() const; // as given to the constructor
    const FmuOptions& options() const;
    const ModelDescription& modelDescription() const;
    bool hasVariable(const std::string& name) const;
    const Variable& variable(const std::string& name) const;
    std::string
    resourceLocation() const; // file:// URI of the unpacked resources folder
    std::string
    unpackDirectory() const; // the temporary directory the FMU is unpacked in

    struct Impl;

private:
    friend class Instance;
    Fmu(std::shared_ptr<Impl> impl, const std::string& path);
    std::shared_ptr<Impl> impl_;
    std::string path_;
    FmuOptions options_;
};

// The SHA-256 of the file at path, 64 lowercase hexadecimal digits (as
// sha256sum prints it); Error naming the file when it cannot be read. A
// case that names the hash of the .fmu it was set up with is sure to run
// that file: an FMU is native code, run with the rights of its host.
std::string fileSha256(const std::string& path);

} // namespace fmuImport

#endif

// The process-wide registry of live unpack directories, removed on the
// paths that skip destructors: exit() (OpenFOAM's FatalError), fatal
// signals and termination requests. Its handlers also name the FMU call
// that a fault or an exit() happens in (CallReport).
#ifndef FMUIMPORT_UNPACKREGISTRY_HPP
#define FMUIMPORT_UNPACKREGISTRY_HPP

#include <string>

namespace fmuImport {

class UnpackRegistry {
public:
    struct Slot;

    // Registers directory, to be removed at exit and on SIGINT, SIGTERM,
    // SIGHUP, SIGQUIT, SIGPIPE, SIGSEGV, SIGFPE, SIGABRT, SIGBUS and SIGILL.
    // The first registration
    // installs the atexit handler and the signal handlers; a signal whose
    // disposition is SIG_IGN then is left alone. Returns nullptr if the path
    // is too long to keep (the directory is then removed by its owner only).
    static Slot* add(const std::string& directory);

    // Forgets the directory (its owner removes it); null is ignored.
    static void remove(Slot* slot) noexcept;

    // Removes every registered directory this process created (not those of
    // a parent before fork). Async-signal-safe.
    static void removeAll() noexcept;
};

} // namespace fmuImport

#endif

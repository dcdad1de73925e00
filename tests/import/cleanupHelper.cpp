// A process that loads an FMU and then ends without destroying it, for the
// importer's cleanup tests (fmuImportCleanupTest.cpp runs it with TMPDIR set
// to an empty directory and checks the directory is empty afterwards).
//
//   fmuImportCleanupHelper <fmu> <how> <marker file>
//
// how:
//   exit          exit(1), as OpenFOAM's FatalError does
//   term, int     raise the signal
//   segv          store to a page without access
//   abort         abort()
//   term-before   install a handler before loading the FMU, then raise
//                 SIGTERM; the handler writes the marker, resets SIGTERM to
//                 its default and raises it again (OpenFOAM's sigInt/sigSegv
//                 pattern)
//   term-after, segv-after
//                 the same handler, installed after loading the FMU; it
//                 restores the handler it replaced before raising again
//   stack-overflow
//                 install a SIGSEGV handler on an alternate stack before
//                 loading the FMU (as fmusim does), then overflow the stack
//   ill           an illegal instruction (__builtin_trap)
//   term-graceful a handler that only writes the marker (a program that
//                 stops at its next write); the process goes on: the unpack
//                 directory must still be there, then it returns normally
#include "fmuImport/fmuImport.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>

namespace {

const char* markerFile = nullptr;
struct sigaction replaced[NSIG];

void writeMarker(const char* text)
{
    const int fd = open(markerFile, O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd < 0)
        return;
    const ssize_t written = write(fd, text, std::strlen(text));
    (void)written;
    close(fd);
}

extern "C" void resetAndRaise(int sig)
{
    writeMarker("handler ran\n");
    sigaction(sig, &replaced[sig], nullptr);
    raise(sig);
}

extern "C" void onlyMark(int)
{
    writeMarker("handler ran\n");
}

void install(int sig, void (*handler)(int), int flags = 0)
{
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = handler;
    action.sa_flags = flags;
    sigemptyset(&action.sa_mask);
    sigaction(sig, &action, &replaced[sig]);
}

volatile bool deeper
    = true; // always true; keeps the compiler from calling the recursion infinite

// Does not return: each frame keeps 4 KiB of stack until the stack is gone.
int recurse(int depth)
{
    volatile char frame[4096];
    frame[depth % sizeof frame] = static_cast<char>(depth);
    return (deeper ? recurse(depth + 1) : 0) + frame[0];
}

char alternateStack[64 * 1024];

} // namespace

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::cerr << "usage: " << argv[0] << " <fmu> <how> <marker file>\n";
        return 2;
    }
    const std::string how = argv[2];
    markerFile = argv[3];
    const rlimit noCore = {0, 0};
    setrlimit(RLIMIT_CORE, &noCore);

    if (how == "term-before")
        install(SIGTERM, resetAndRaise);
    if (how == "stack-overflow") {
        stack_t stack {};
        stack.ss_sp = alternateStack;
        stack.ss_size = sizeof alternateStack;
        sigaltstack(&stack, nullptr);
        install(SIGSEGV, resetAndRaise, SA_ONSTACK);
    }
    fmuImport::Fmu fmu(argv[1]);
    fmuImport::Instance instance(fmu, "cleanup");
    const std::filesystem::path unpacked = fmu.unpackDirectory();
    if (how == "term-after")
        install(SIGTERM, resetAndRaise);
    if (how == "segv-after")
        install(SIGSEGV, resetAndRaise);
    if (how == "term-graceful")
        install(SIGTERM, onlyMark);

    if (how == "exit")
        std::exit(1);
    if (how == "term" || how == "term-before" || how == "term-after"
        || how == "term-graceful")
        raise(SIGTERM);
    if (how == "int")
        raise(SIGINT);
    if (how == "segv" || how == "segv-after") {
        // A real fault, without undefined behaviour for UBSan to catch
        // first: a store to a page without access.
        void* page = mmap(nullptr, 4096, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS,
                          -1, 0);
        *static_cast<volatile int*>(page) = 1;
    }
    if (how == "abort")
        std::abort();
    if (how == "stack-overflow")
        return recurse(0);
    if (how == "ill")
        __builtin_trap();

    if (how == "term-graceful") {
        // Still running: the FMU's files must still be there.
        if (!std::filesystem::exists(unpacked / "modelDescription.xml")) {
            std::cerr
                << "the unpack directory was removed while the process went on\n";
            return 3;
        }
        return 0;
    }
    std::cerr << "unknown how '" << how << "'\n";
    return 2;
}

#include "UnpackRegistry.hpp"

#include "CallReport.hpp"
#include "RemoveTree.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace fmuImport {

// A slot is free, being filled, live, or claimed by removeAll. Slots come
// in chunks that are never freed, so a signal handler walking them never
// meets freed memory; the path is written before the slot is published as
// live (release) and read only after seeing it live (acquire).
struct UnpackRegistry::Slot {
    enum State { free, filling, live, removing };
    std::atomic<int> state {free};
    pid_t owner = 0;
    char path[PATH_MAX] = "";
};

namespace {

constexpr int slotsPerChunk = 16;

struct Chunk {
    UnpackRegistry::Slot slots[slotsPerChunk];
    Chunk* next = nullptr;
};

std::atomic<Chunk*> chunks {nullptr};
std::mutex addMutex; // serialises add(); removeAll() needs no lock

const int handledSignals[] = {SIGINT,  SIGTERM, SIGHUP,  SIGQUIT, SIGPIPE,
                              SIGSEGV, SIGFPE,  SIGABRT, SIGBUS,  SIGILL};
struct sigaction
    previousActions[NSIG]; // written once, before our handlers are installed

bool isFault(int sig)
{
    return sig == SIGSEGV || sig == SIGFPE || sig == SIGABRT || sig == SIGBUS
        || sig == SIGILL;
}

bool isDefault(const struct sigaction& action)
{
    return !(action.sa_flags & SA_SIGINFO) && action.sa_handler == SIG_DFL;
}

// Names the FMU call in progress if a fault (SIGSEGV, SIGFPE, SIGABRT,
// SIGBUS, SIGILL) hit it (CallReport), runs the host's ending hook and
// removes the directories (processEnds), then hands
// the signal to whatever handled it before (OpenFOAM's stack trace). The directory removal uses only async-signal-safe calls (see
// RemoveTree.hpp): the process may be stopped anywhere, in malloc or
// holding a lock, and is about to die.
//  - A fault (SIGSEGV, SIGFPE, SIGABRT, SIGBUS, SIGILL) ends the process:
//    remove first, then chain.
//  - SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE may be handled by a program that goes on, such
//    as OpenFOAM's stopAtWriteNow, which needs its FMU files until it
//    stops: remove first only if the previous disposition was the default
//    one; otherwise call the previous handler and remove only if it reset
//    the disposition to the default to re-raise the signal (OpenFOAM's
//    handlers do this), that is, if the process is about to die.
// A default disposition is restored and the signal raised again: it is
// blocked while we run, so it is delivered, with its default action and
// exit status, when this handler returns.
extern "C" void onFatalSignal(int sig, siginfo_t* info, void* context)
{
    const int savedErrno = errno;
    const struct sigaction& previous = previousActions[sig];
    if (isFault(sig))
        reportCrash(sig);
    if (isFault(sig) || isDefault(previous))
        processEnds();
    if (isDefault(previous)) {
        sigaction(sig, &previous, nullptr);
        raise(sig);
    } else {
        if (previous.sa_flags & SA_SIGINFO)
            previous.sa_sigaction(sig, info, context);
        else if (previous.sa_handler != SIG_IGN)
            previous.sa_handler(sig);
        struct sigaction now;
        if (!isFault(sig) && sigaction(sig, nullptr, &now) == 0
            && isDefault(now))
            processEnds();
    }
    errno = savedErrno;
}

extern "C" void removeAllAtExit()
{
    UnpackRegistry::removeAll();
}

// The handlers below are code of the importer, which may live in a shared
// library the host loaded with dlopen and closes before it exits
// (OpenFOAM's libs entry): kept loaded (RTLD_NODELETE), so that the exit
// hook and a late signal never jump into unmapped code.
void keepLoaded()
{
    Dl_info info;
    if (dladdr(reinterpret_cast<void*>(&keepLoaded), &info) && info.dli_fname)
        dlopen(info.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
}

void installHandlers()
{
    keepLoaded();
    // Registered first, so that it runs last: after the removal below
    installExitReport();
    std::atexit(removeAllAtExit);
    for (const int sig : handledSignals) {
        struct sigaction previous;
        if (sigaction(sig, nullptr, &previous) != 0)
            continue;
        if (!(previous.sa_flags & SA_SIGINFO) && previous.sa_handler == SIG_IGN)
            continue; // nohup, background jobs
        previousActions[sig] = previous;
        struct sigaction action;
        std::memset(&action, 0, sizeof action);
        action.sa_sigaction = onFatalSignal;
        // SA_ONSTACK: on the alternate stack when the thread has one (fmusim
        // sets one up to report stack overflows in an FMU); removal needs
        // about 1.5 KiB of stack.
        action.sa_flags
            = SA_SIGINFO | SA_ONSTACK | (previous.sa_flags & SA_RESTART);
        sigemptyset(&action.sa_mask);
        sigaction(sig, &action, nullptr);
    }
}

} // namespace

UnpackRegistry::Slot* UnpackRegistry::add(const std::string& directory)
{
    if (directory.size() >= PATH_MAX)
        return nullptr;
    static std::once_flag installed;
    std::call_once(installed, installHandlers);

    const std::lock_guard<std::mutex> lock(addMutex);
    Slot* slot = nullptr;
    for (Chunk* c = chunks.load(std::memory_order_acquire); c && !slot;
         c = c->next) {
        for (Slot& s : c->slots) {
            int expected = Slot::free;
            if (s.state.compare_exchange_strong(expected, Slot::filling)) {
                slot = &s;
                break;
            }
        }
    }
    if (!slot) {
        Chunk* c = new Chunk; // never freed: see Slot
        c->next = chunks.load(std::memory_order_relaxed);
        slot = &c->slots[0];
        slot->state.store(Slot::filling, std::memory_order_relaxed);
        chunks.store(c, std::memory_order_release);
    }
    std::memcpy(slot->path, directory.c_str(), directory.size() + 1);
    slot->owner = getpid();
    slot->state.store(Slot::live, std::memory_order_release);
    return slot;
}

void UnpackRegistry::remove(Slot* slot) noexcept
{
    if (!slot)
        return;
    int expected = Slot::live;
    slot->state.compare_exchange_strong(
        expected, Slot::free); // fails only if removeAll has claimed it
}

void UnpackRegistry::removeAll() noexcept
{
    const pid_t self = getpid();
    for (Chunk* c = chunks.load(std::memory_order_acquire); c; c = c->next) {
        for (Slot& s : c->slots) {
            if (s.state.load(std::memory_order_acquire) != Slot::live
                || s.owner != self)
                continue;
            int expected = Slot::live;
            if (s.state.compare_exchange_strong(expected, Slot::removing))
                removeTreeSignalSafe(s.path);
        }
    }
}

} // namespace fmuImport

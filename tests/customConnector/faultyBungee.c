/* faultyBungee: the example connector examples/customConnector/bungee.c,
   unchanged, with a fault inside fmi2DoStep: the steps from t = FAULT_TIME
   on (0.25 s unless defined) do what FAULT_<KIND> says before stepping,
   for the reliability tests of fmusim and the bridge (a connector written
   by a third party that misbehaves):

       FAULT_SEGFAULT        writes through a null pointer (SIGSEGV)
       FAULT_DIVIDE_BY_ZERO  divides an integer by zero (SIGFPE, whatever
                             the floating-point traps)
       FAULT_ABORT           calls abort() (SIGABRT)
       FAULT_HANG            never returns
       FAULT_EXIT            calls exit(0): the process ends "successfully"
       FAULT_WRITE_FD3       writes bytes to file descriptor 3 (where a
                             socket to the host often is)
       FAULT_WRITE_SOCKETS   writes bytes to every socket among its open
                             descriptors (/proc/self/fd)
       FAULT_CLOSE_FDS       closes descriptors 0 to 63
       FAULT_CLOSE_ALL_FDS   closes every descriptor, up to the limit of
                             open files

   The last four then step as the bungee does.

   The example's fmi2DoStep is renamed before its file is included, and
   called when no fault is due. */
#define fmi2DoStep bungeeDoStep
#include "bungee.c"
#undef fmi2DoStep

#include <dirent.h>
#include <sys/resource.h>
#include <unistd.h>

#ifndef FAULT_TIME
#define FAULT_TIME 0.25
#endif

static void fault(void)
{
#if defined(FAULT_SEGFAULT)
    /* volatile all through, or the compiler may drop the store */
    volatile int* volatile nowhere = NULL;
    *nowhere = 1;
#elif defined(FAULT_DIVIDE_BY_ZERO)
    /* neither operand known, or the compiler computes 1 / x without idiv */
    volatile int one = 1, zero = 0;
    volatile int quotient = one / zero;
    (void)quotient;
#elif defined(FAULT_ABORT)
    abort();
#elif defined(FAULT_HANG)
    volatile int spinning = 1;
    while (spinning) { }
#elif defined(FAULT_EXIT)
    exit(0);
#elif defined(FAULT_WRITE_FD3)
    static const char stray[] = "stray bytes!";
    ssize_t written = write(3, stray, sizeof stray - 1);
    (void)written;
#elif defined(FAULT_WRITE_SOCKETS)
    static const char stray[] = "stray bytes!";
    DIR* fds = opendir("/proc/self/fd");
    struct dirent* e;
    while (fds && (e = readdir(fds)) != NULL) {
        char path[300], target[64];
        snprintf(path, sizeof path, "/proc/self/fd/%s", e->d_name);
        const ssize_t n = readlink(path, target, sizeof target - 1);
        if (n > 0 && strncmp(target, "socket:", 7) == 0) {
            ssize_t written = write(atoi(e->d_name), stray, sizeof stray - 1);
            (void)written;
        }
    }
    if (fds)
        closedir(fds);
#elif defined(FAULT_CLOSE_FDS)
    for (int fd = 0; fd < 64; ++fd)
        close(fd);
#elif defined(FAULT_CLOSE_ALL_FDS)
    struct rlimit limit;
    getrlimit(RLIMIT_NOFILE, &limit);
    for (rlim_t fd = 0; fd < limit.rlim_cur && fd < 65536; ++fd)
        close((int)fd);
#else
#error                                                                         \
    "define one of FAULT_SEGFAULT, FAULT_DIVIDE_BY_ZERO, FAULT_ABORT, FAULT_HANG, FAULT_EXIT, FAULT_WRITE_FD3, FAULT_WRITE_SOCKETS, FAULT_CLOSE_FDS, FAULT_CLOSE_ALL_FDS"
#endif
}

FMI2_Export fmi2DoStepTYPE fmi2DoStep;

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    if (currentCommunicationPoint >= FAULT_TIME)
        fault();
    return bungeeDoStep(c, currentCommunicationPoint, communicationStepSize,
                        noSetFMUStatePriorToCurrentPoint);
}

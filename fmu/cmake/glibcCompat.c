/* Linked into every connector FMU binary (fmu/cmake/ConnectorFmu.cmake),
   which carries its own libstdc++ (-static-libstdc++) so that it runs
   beside any host's C++ runtime. That libstdc++.a, and the FMU's own code,
   were compiled against Debian 12's glibc 2.36 and would refuse to load on
   any older glibc for a handful of symbols. Each has an older equivalent
   and is bound to it here:

   - hypot (2.35) and pow (2.29) got new symbol versions for faster code;
     the old versions compute the same functions;
   - getentropy (2.25) and arc4random (2.36) come with std::random_device,
     which libstdc++.a links in but the FMUs never call: the getrandom
     system call serves both;
   - __libc_single_threaded (2.32) tells libstdc++ whether it may skip
     atomic operations; defined here as false, it always uses them, which
     is correct in any process;
   - pthread_once (2.34), called by libstdc++.a, moved from libpthread into
     libc in 2.34; its first version, GLIBC_2.2.5, is the same function. An
     older glibc has that version in libpthread.so.0 only, so the binary
     also needs libpthread.so.0 (ConnectorFmu.cmake links it with
     --no-as-needed; since 2.34 an empty library kept for such binaries).

   What remains is memcpy (2.14), so the FMUs load on glibc 2.17 or later
   (the manylinux2014 level: RHEL/CentOS 7, Debian 10, Ubuntu 18.04), as
   tests/fmu/checkBinary.cmake checks; tests/fmu/oldGlibc steps every FMU
   in a Debian 11 root (glibc 2.31).

   The linker redirects the calls here with -Wl,--wrap=<symbol>. */
#define _GNU_SOURCE
#include <errno.h>
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/syscall.h>
#include <unistd.h>

char __libc_single_threaded = 0;

double hypotGlibc225(double x, double y);
__asm__(".symver hypotGlibc225, hypot@GLIBC_2.2.5");
double __wrap_hypot(double x, double y)
{
    return hypotGlibc225(x, y);
}

double powGlibc225(double x, double y);
__asm__(".symver powGlibc225, pow@GLIBC_2.2.5");
double __wrap_pow(double x, double y)
{
    return powGlibc225(x, y);
}

int pthreadOnceGlibc225(pthread_once_t* control, void (*init)(void));
__asm__(".symver pthreadOnceGlibc225, pthread_once@GLIBC_2.2.5");
int __wrap_pthread_once(pthread_once_t* control, void (*init)(void))
{
    return pthreadOnceGlibc225(control, init);
}

int __wrap_getentropy(void* buffer, size_t length)
{
    if (length > 256) {
        errno = EIO;
        return -1;
    }
    char* p = buffer;
    while (length > 0) {
        const long got = syscall(SYS_getrandom, p, length, 0);
        if (got < 0) {
            if (errno == EINTR)
                continue;
            return -1;
        }
        p += got;
        length -= (size_t)got;
    }
    return 0;
}

uint32_t __wrap_arc4random(void)
{
    uint32_t value = 0;
    while (__wrap_getentropy(&value, sizeof value) != 0) { }
    return value;
}

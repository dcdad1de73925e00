#include "RemoveTree.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace fmuImport {

namespace {

// The record getdents64 fills (see getdents64(2)); glibc 2.36 has no
// wrapper for the system call.
struct Dirent64 {
    std::uint64_t d_ino;
    std::int64_t d_off;
    unsigned short d_reclen;
    unsigned char d_type;
    char d_name[1];
};

constexpr int maxDepth = 32;
constexpr long maxSteps
    = 10000; // bounds the work on a tree that cannot be emptied

bool isDotOrDotDot(const char* name)
{
    return name[0] == '.' && (!name[1] || (name[1] == '.' && !name[2]));
}

} // namespace

// Depth first without recursion: the open directories are a stack of file
// descriptors, and a directory is read again from its start after one of
// its subdirectories was emptied (removed entries do not come back), so one
// 1 KiB buffer serves every level.
void removeTreeSignalSafe(const char* path) noexcept
{
    const int savedErrno = errno;
    int fds[maxDepth];
    int depth = 0;
    fds[0] = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fds[0] < 0) {
        unlink(path);
        errno = savedErrno;
        return;
    }
    alignas(8) char buffer[1024];
    long steps = 0;
    while (depth >= 0 && ++steps < maxSteps) {
        const int fd = fds[depth];
        lseek(fd, 0, SEEK_SET);
        bool descended = false;
        long n = 0;
        while (!descended
               && (n = syscall(SYS_getdents64, fd, buffer, sizeof buffer))
                   > 0) {
            for (long offset = 0; offset < n && !descended;) {
                const Dirent64* entry
                    = reinterpret_cast<const Dirent64*>(buffer + offset);
                offset += entry->d_reclen;
                const char* name = entry->d_name;
                if (isDotOrDotDot(name))
                    continue;
                if (entry->d_type != DT_DIR && unlinkat(fd, name, 0) == 0)
                    continue;
                if (unlinkat(fd, name, AT_REMOVEDIR) == 0
                    || depth + 1 >= maxDepth)
                    continue;
                const int sub = openat(
                    fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
                if (sub < 0)
                    continue;
                fds[++depth] = sub;
                descended = true;
            }
        }
        if (descended)
            continue;
        close(fd);
        --depth;
    }
    while (depth >= 0)
        close(fds[depth--]);
    rmdir(path);
    errno = savedErrno;
}

} // namespace fmuImport

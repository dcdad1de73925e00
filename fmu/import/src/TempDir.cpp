#include "TempDir.hpp"

#include "UnpackRegistry.hpp"
#include "fmuImport/fmuImport.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>
#include <string>
#include <system_error>

namespace fmuImport {

namespace {

// The process id of an unpack directory's name, fmuImport-<pid>-XXXXXX
// (mkdtemp's six letters and digits), or 0 for any other name.
long processOf(const std::string& name)
{
    const std::string prefix = "fmuImport-";
    if (name.compare(0, prefix.size(), prefix) != 0)
        return 0;
    const std::size_t dash = name.find('-', prefix.size());
    if (dash == std::string::npos || dash == prefix.size()
        || name.size() != dash + 7)
        return 0;
    long pid = 0;
    for (std::size_t i = prefix.size(); i < dash; ++i) {
        if (!std::isdigit(static_cast<unsigned char>(name[i])) || pid > 1 << 24)
            return 0;
        pid = 10 * pid + (name[i] - '0');
    }
    for (std::size_t i = dash + 1; i < name.size(); ++i) {
        if (!std::isalnum(static_cast<unsigned char>(name[i])))
            return 0;
    }
    return pid;
}

// Removes the unpack directories in base that a process of this user left
// behind when it was killed (SIGKILL skips every handler, a node goes
// down): a directory, not a link, named fmuImport-<pid>-XXXXXX, owned by
// this user, whose process no longer exists (no /proc/<pid>). A process of
// that id that exists now, even another program, keeps the directory.
// Once per base directory and process.
void removeLeftovers(const std::filesystem::path& base)
{
    static std::mutex mutex;
    static std::set<std::string> swept;
    const std::lock_guard<std::mutex> lock(mutex);
    if (!swept.insert(base.string()).second)
        return;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(base, ec), end;
         !ec && it != end; it.increment(ec)) {
        const std::filesystem::path path = it->path();
        const long pid = processOf(path.filename().string());
        struct stat st;
        if (pid <= 0 || pid == getpid() || lstat(path.c_str(), &st) != 0
            || !S_ISDIR(st.st_mode) || st.st_uid != geteuid())
            continue;
        struct stat process;
        if (stat(("/proc/" + std::to_string(pid)).c_str(), &process) == 0
            || errno != ENOENT)
            continue;
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
}

} // namespace

TempDir::TempDir()
{
    std::error_code ec;
    std::filesystem::path base = std::filesystem::temp_directory_path(ec);
    if (ec)
        base = "/tmp";
    removeLeftovers(base);
    // The process id in the name lets a check tell a directory left behind
    // by a dead process from one in use (tests/import's leftover check).
    std::string pattern
        = (base / ("fmuImport-" + std::to_string(getpid()) + "-XXXXXX"))
              .string();
    if (!mkdtemp(pattern.data()))
        throw Error("cannot create a temporary directory from '" + pattern
                    + "': " + std::strerror(errno));
    path_ = pattern;
    slot_ = UnpackRegistry::add(path_.string());
}

TempDir::~TempDir()
{
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    UnpackRegistry::remove(slot_);
}

} // namespace fmuImport

#include "TempDir.hpp"

#include "UnpackRegistry.hpp"
#include "fmuImport/fmuImport.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace fmuImport {

TempDir::TempDir()
{
    std::error_code ec;
    std::filesystem::path base = std::filesystem::temp_directory_path(ec);
    if (ec)
        base = "/tmp";
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

// A private temporary directory (mkdtemp: $TMPDIR/fmuImport-<pid>-XXXXXX),
// removed with its contents when the object is destroyed, or, when the
// process ends without destroying it, by UnpackRegistry. A process killed
// by SIGKILL leaves its directory behind: the first TempDir a process makes
// in a temporary folder removes there the directories of that naming owned
// by its user whose process has ended.
#ifndef FMUIMPORT_TEMPDIR_HPP
#define FMUIMPORT_TEMPDIR_HPP

#include "UnpackRegistry.hpp"

#include <filesystem>

namespace fmuImport {

class TempDir {
public:
    TempDir(); // throws Error
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    UnpackRegistry::Slot* slot_ = nullptr;
};

} // namespace fmuImport

#endif

// A private temporary directory (mkdtemp), removed with its contents when
// the object is destroyed.
#ifndef FMUIMPORT_TEMPDIR_HPP
#define FMUIMPORT_TEMPDIR_HPP

#include <filesystem>

namespace fmuImport {

class TempDir
{
public:
    TempDir();  // throws Error
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace fmuImport

#endif

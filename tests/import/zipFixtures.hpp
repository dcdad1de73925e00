// Helpers for importer tests: FMU fixture paths, archives with hostile
// entries (built with libzip, since cmake -E tar cannot write them) and a
// private TMPDIR to see what the importer leaves behind.
#ifndef TESTS_IMPORT_ZIPFIXTURES_HPP
#define TESTS_IMPORT_ZIPFIXTURES_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace fixtures {

// <build>/tests/fixture-fmus/<name>.fmu
std::string fmuPath(const std::string& name);

struct ZipEntry
{
    std::string name;
    std::string content;  // the link target for a symbolic link
    bool symlink = false;
};

// Copies the archive source to target and adds entries to the copy.
void copyWithEntries(const std::string& source, const std::string& target, const std::vector<ZipEntry>& entries);

// Points TMPDIR at a fresh empty directory for the lifetime of the object
// and restores it afterwards.
class PrivateTmpDir
{
public:
    PrivateTmpDir();
    ~PrivateTmpDir();
    PrivateTmpDir(const PrivateTmpDir&) = delete;
    PrivateTmpDir& operator=(const PrivateTmpDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::vector<std::string> contents() const;  // names of the entries in the directory

private:
    std::filesystem::path path_;
    std::string previous_;
    bool hadPrevious_ = false;
};

}  // namespace fixtures

#endif

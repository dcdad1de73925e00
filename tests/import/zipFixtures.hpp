// Helpers for importer tests: FMU fixture paths, archives with hostile
// entries (built with libzip, since cmake -E tar cannot write them), a
// private TMPDIR to see what the importer leaves behind, and the check of
// an importer error's message.
#ifndef TESTS_IMPORT_ZIPFIXTURES_HPP
#define TESTS_IMPORT_ZIPFIXTURES_HPP

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "fmuImport/fmuImport.hpp"

namespace fixtures {

// call() throws fmuImport::Error saying `part` in its message; else a
// failure saying `otherwise`
template <class Call>
void expectErrorSaying(Call&& call, const std::string& part,
                       const std::string& otherwise)
{
    try {
        call();
        ADD_FAILURE() << otherwise;
    } catch (const fmuImport::Error& e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
            << e.what();
    }
}

// <build>/tests/fixture-fmus/<name>.fmu
std::string fmuPath(const std::string& name);

struct ZipEntry {
    std::string name;
    std::string content; // the link target for a symbolic link
    bool symlink = false;
};

// Copies the archive source to target and adds entries to the copy.
void copyWithEntries(const std::string& source, const std::string& target,
                     const std::vector<ZipEntry>& entries);

// Writes a new archive holding entries.
void writeArchive(const std::string& target,
                  const std::vector<ZipEntry>& entries);

// Adds an entry of size zero bytes, streamed (deflated, so a 300 MiB entry
// takes about 300 KiB in the archive), to the archive at path.
void addZeroEntry(const std::string& path, const std::string& name,
                  std::uint64_t size);

// Rewrites the uncompressed size of the entry name in the archive's local
// header and central directory: a zip directory that lies.
void patchDeclaredSize(const std::string& path, const std::string& name,
                       std::uint32_t size);

// Renames the entry from to to (a name of the same length) in the archive's
// local header and central directory, without libzip, which refuses a name
// that is already taken: an archive with two entries of one name.
void renameEntry(const std::string& path, const std::string& from,
                 const std::string& to);

// Sets an environment variable for the lifetime of the object.
class ScopedEnv {
public:
    ScopedEnv(const std::string& name, const std::string& value);
    ~ScopedEnv();
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    std::string name_, previous_;
    bool hadPrevious_;
};

// Limits the size of any file this process writes (RLIMIT_FSIZE) for the
// lifetime of the object, SIGXFSZ ignored: a larger write fails with EFBIG.
// Shows that nothing large was written.
class FileSizeLimit {
public:
    explicit FileSizeLimit(std::uint64_t bytes);
    ~FileSizeLimit();
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    std::uint64_t previous_;
    void (*previousHandler_)(int);
};

// Points TMPDIR at a fresh empty directory for the lifetime of the object
// and restores it afterwards.
class PrivateTmpDir {
public:
    PrivateTmpDir();
    ~PrivateTmpDir();
    PrivateTmpDir(const PrivateTmpDir&) = delete;
    PrivateTmpDir& operator=(const PrivateTmpDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::vector<std::string>
    contents() const; // names of the entries in the directory

private:
    std::filesystem::path path_;
    std::string previous_;
    bool hadPrevious_ = false;
};

} // namespace fixtures

#endif

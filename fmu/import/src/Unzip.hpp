// Reading an FMU archive with libzip, within limits.
//
// Only what the importer uses is unpacked: modelDescription.xml, the
// binary binaries/linux64/<modelIdentifier>.so and everything under
// resources/. Before anything is written, the uncompressed sizes the zip
// directory declares are checked against the limits; while writing, the
// bytes are counted, since the directory can lie, and unpacking stops at
// the declared size:
//   - at most 256 MiB (maxEntryBytes) per entry,
//   - at most 1 GiB in total, or the number of bytes in the environment
//     variable FMUIMPORT_MAX_UNPACK_BYTES; an entry is then also limited to
//     that total.
#ifndef FMUIMPORT_UNZIP_HPP
#define FMUIMPORT_UNZIP_HPP

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

struct zip;

namespace fmuImport {

constexpr std::uint64_t maxEntryBytes = std::uint64_t(256) << 20;
constexpr std::uint64_t defaultMaxUnpackBytes = std::uint64_t(1) << 30;
constexpr const char* maxUnpackBytesVariable = "FMUIMPORT_MAX_UNPACK_BYTES";

struct UnpackLimits {
    std::uint64_t perEntry = maxEntryBytes;
    std::uint64_t total = defaultMaxUnpackBytes;

    // The defaults, with total from FMUIMPORT_MAX_UNPACK_BYTES when set;
    // an Error naming the variable when it is not a positive integer.
    static UnpackLimits fromEnvironment();
    std::string describe() const; // for error messages
};

class FmuArchive {
public:
    // Opens the archive and checks every entry name: absolute names, '..'
    // components, backslashes and symbolic links are refused with an Error
    // naming the archive and the entry, and so are two file entries of one
    // name (after normalisation: "./a" is "a").
    FmuArchive(const std::string& archive, UnpackLimits limits);
    ~FmuArchive();
    FmuArchive(const FmuArchive&) = delete;
    FmuArchive& operator=(const FmuArchive&) = delete;

    // Whether a file entry of this (normalised) name exists.
    bool has(const std::string& name) const;

    // The whole entry, in memory; counts against the limits.
    std::string read(const std::string& name);

    // Writes the entry named file (counted against the limits) and every
    // entry under the folder prefix (such as "resources/") into directory.
    // The limits are checked on the declared sizes before anything is
    // written.
    void extract(const std::string& file, const std::string& prefix,
                 const std::filesystem::path& directory);

    // Writes bytes as directory/name (bytes read with read()).
    void write(const std::string& name, const std::string& bytes,
               const std::filesystem::path& directory) const;

private:
    struct Entry {
        std::uint64_t index;
        std::uint64_t size; // as the zip directory declares it
        bool isDirectory;
    };

    std::string where(const std::string& name) const;
    std::uint64_t
    charge(const std::string& name,
           std::uint64_t size) const; // checks one entry's declared size
    template <class Sink>
    void copy(const std::string& name, const Entry& entry, Sink sink);

    std::string archive_;
    UnpackLimits limits_;
    std::unique_ptr<zip, void (*)(zip*)> zip_;
    std::map<std::string, Entry> entries_; // normalised name -> entry
    std::uint64_t unpacked_ = 0; // bytes read or written so far
};

} // namespace fmuImport

#endif

#include "Unzip.hpp"

#include "fmuImport/fmuImport.hpp"

#include <sys/stat.h>
#include <zip.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <vector>

namespace fmuImport {

namespace {

struct EntryCloser {
    void operator()(zip_file_t* f) const { zip_fclose(f); }
};

std::string inQuotes(const std::string& s)
{
    return "'" + s + "'";
}

// The entry's name as a normalised relative path ("a/./b/" -> "a/b/"), or
// an Error for one that could escape the target directory.
std::string safeRelativeName(const std::string& archive,
                             const std::string& name)
{
    const std::string where
        = "FMU " + inQuotes(archive) + ": archive entry " + inQuotes(name);
    if (name.empty() || name.front() == '/')
        throw Error(where + " has an absolute path");
    if (name.find('\\') != std::string::npos)
        throw Error(where + " contains a backslash");
    const std::filesystem::path path(name);
    for (const auto& part : path) {
        if (part == "..")
            throw Error(where + " has a '..' component");
    }
    return path.lexically_normal().generic_string();
}

bool isSymlink(zip_t* z, zip_uint64_t index)
{
    zip_uint8_t system = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(z, index, 0, &system, &attributes)
        != 0)
        return false;
    return system == ZIP_OPSYS_UNIX && S_ISLNK(attributes >> 16);
}

} // namespace

UnpackLimits UnpackLimits::fromEnvironment()
{
    UnpackLimits limits;
    if (const char* value = std::getenv(maxUnpackBytesVariable)) {
        char* end = nullptr;
        errno = 0;
        const unsigned long long total = std::strtoull(value, &end, 10);
        if (end == value || *end != '\0' || errno == ERANGE || total == 0
            || value[0] == '-')
            throw Error(std::string("environment variable ")
                        + maxUnpackBytesVariable + " is '" + value
                        + "', expected a positive number of bytes");
        limits.total = total;
        if (limits.perEntry > total)
            limits.perEntry = total;
    }
    return limits;
}

std::string UnpackLimits::describe() const
{
    return "limits: " + std::to_string(perEntry) + " bytes per entry, "
        + std::to_string(total) + " bytes in total; the environment variable "
        + maxUnpackBytesVariable + " sets the total (default "
        + std::to_string(defaultMaxUnpackBytes) + ", at most "
        + std::to_string(maxEntryBytes) + " per entry)";
}

FmuArchive::FmuArchive(const std::string& archive, UnpackLimits limits)
    : archive_(archive), limits_(limits),
      zip_(nullptr, [](zip* z) { zip_discard(z); })
{
    int code = 0;
    zip_.reset(zip_open(archive.c_str(), ZIP_RDONLY, &code));
    if (!zip_) {
        zip_error_t error;
        zip_error_init_with_code(&error, code);
        const std::string reason = zip_error_strerror(&error);
        zip_error_fini(&error);
        throw Error("FMU " + inQuotes(archive)
                    + " cannot be opened as a zip archive: " + reason);
    }

    const zip_int64_t n = zip_get_num_entries(zip_.get(), 0);
    for (zip_int64_t i = 0; i < n; ++i) {
        const char* rawName = zip_get_name(zip_.get(), i, ZIP_FL_ENC_GUESS);
        const std::string name = rawName ? rawName : "";
        const std::string relative = safeRelativeName(archive, name);
        if (isSymlink(zip_.get(), i))
            throw Error(where(name) + " is a symbolic link");
        zip_stat_t st;
        zip_stat_init(&st);
        if (zip_stat_index(zip_.get(), i, 0, &st) != 0
            || !(st.valid & ZIP_STAT_SIZE))
            throw Error(where(name) + " has no size in the zip directory: "
                        + zip_strerror(zip_.get()));
        const bool isDirectory = name.back() == '/';
        const auto [found, added] = entries_.emplace(
            relative,
            Entry {static_cast<std::uint64_t>(i), st.size, isDirectory});
        // Which of two files of one name counts depends on the tool that
        // reads the archive (the first, the last): neither may be trusted.
        if (!added && !(isDirectory && found->second.isDirectory))
            throw Error(where(name) + " appears twice"
                        + (name == relative ? std::string()
                                            : " (as '" + relative + "')")
                        + ": an FMU names each file once, else tools may "
                          "read different ones");
    }
}

FmuArchive::~FmuArchive() = default;

std::string FmuArchive::where(const std::string& name) const
{
    return "FMU " + inQuotes(archive_) + ": archive entry " + inQuotes(name);
}

bool FmuArchive::has(const std::string& name) const
{
    const auto found = entries_.find(name);
    return found != entries_.end() && !found->second.isDirectory;
}

std::uint64_t FmuArchive::charge(const std::string& name,
                                 std::uint64_t size) const
{
    if (size > limits_.perEntry)
        throw Error(where(name) + " unpacks to " + std::to_string(size)
                    + " bytes, more than the limit of "
                    + std::to_string(limits_.perEntry) + " bytes per entry ("
                    + limits_.describe() + ")");
    return size;
}

// Reads the entry in 64 KiB pieces into sink, counting: it stops with an
// Error as soon as the entry gives more than its declared size (which was
// checked against the limits) or the running total exceeds the limit.
template <class Sink>
void FmuArchive::copy(const std::string& name, const Entry& entry, Sink sink)
{
    std::unique_ptr<zip_file_t, EntryCloser> file(
        zip_fopen_index(zip_.get(), entry.index, 0));
    if (!file)
        throw Error("FMU " + inQuotes(archive_) + ": cannot read archive entry "
                    + inQuotes(name) + ": " + zip_strerror(zip_.get()));
    std::vector<char> buffer(1 << 16);
    std::uint64_t got = 0;
    zip_int64_t n = 0;
    while ((n = zip_fread(file.get(), buffer.data(), buffer.size())) > 0) {
        got += static_cast<std::uint64_t>(n);
        unpacked_ += static_cast<std::uint64_t>(n);
        if (got > entry.size)
            throw Error(where(name) + " unpacks to more than the "
                        + std::to_string(entry.size)
                        + " bytes the zip directory declares; stopped ("
                        + limits_.describe() + ")");
        if (unpacked_ > limits_.total)
            throw Error(where(name)
                        + " brings the unpacked total over the limit of "
                        + std::to_string(limits_.total) + " bytes ("
                        + limits_.describe() + ")");
        sink(buffer.data(), static_cast<std::size_t>(n));
    }
    if (n < 0)
        throw Error(where(name)
                    + " is corrupt: " + zip_file_strerror(file.get()));
    if (got != entry.size)
        throw Error(where(name) + " unpacks to " + std::to_string(got)
                    + " bytes, not the " + std::to_string(entry.size)
                    + " the zip directory declares");
}

std::string FmuArchive::read(const std::string& name)
{
    const auto found = entries_.find(name);
    if (found == entries_.end() || found->second.isDirectory)
        throw Error(where(name) + " does not exist");
    const std::uint64_t size = charge(name, found->second.size);
    if (unpacked_ + size > limits_.total)
        throw Error(where(name) + " unpacks to " + std::to_string(size)
                    + " bytes, more than the limit of "
                    + std::to_string(limits_.total) + " bytes in total ("
                    + limits_.describe() + ")");
    std::string bytes;
    bytes.reserve(static_cast<std::size_t>(size));
    copy(name, found->second,
         [&bytes](const char* data, std::size_t n) { bytes.append(data, n); });
    return bytes;
}

void FmuArchive::write(const std::string& name, const std::string& bytes,
                       const std::filesystem::path& directory) const
{
    const std::filesystem::path target = directory / name;
    std::error_code ec;
    std::filesystem::create_directories(target.parent_path(), ec);
    std::ofstream out(target, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out)
        throw Error("FMU " + inQuotes(archive_) + ": cannot write "
                    + inQuotes(target.string()));
}

void FmuArchive::extract(const std::string& file, const std::string& prefix,
                         const std::filesystem::path& directory)
{
    std::vector<std::pair<std::string, const Entry*>> selected;
    for (const auto& [name, entry] : entries_) {
        if (name == file || name.compare(0, prefix.size(), prefix) == 0)
            selected.emplace_back(name, &entry);
    }
    std::uint64_t total = unpacked_;
    for (const auto& [name, entry] : selected) {
        total += charge(name, entry->size);
        if (total > limits_.total)
            throw Error(where(name) + " (" + std::to_string(entry->size)
                        + " bytes) brings the unpacked total to "
                        + std::to_string(total)
                        + " bytes, more than the limit of "
                        + std::to_string(limits_.total) + " bytes in total ("
                        + limits_.describe() + ")");
    }

    for (const auto& [name, entry] : selected) {
        const std::filesystem::path target = directory / name;
        std::error_code ec;
        std::filesystem::create_directories(
            entry->isDirectory ? target : target.parent_path(), ec);
        if (ec)
            throw Error("FMU " + inQuotes(archive_) + ": cannot create "
                        + inQuotes(target.string()) + ": " + ec.message());
        if (entry->isDirectory)
            continue;
        std::ofstream out(target, std::ios::binary);
        if (!out)
            throw Error("FMU " + inQuotes(archive_) + ": cannot write "
                        + inQuotes(target.string()));
        copy(name, *entry, [&out](const char* data, std::size_t n) {
            out.write(data, static_cast<std::streamsize>(n));
        });
        if (!out)
            throw Error("FMU " + inQuotes(archive_) + ": cannot write "
                        + inQuotes(target.string()));
    }
}

} // namespace fmuImport

#include "zipFixtures.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <zip.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fixtures {

std::string fmuPath(const std::string& name)
{
    return std::string(FIXTURE_FMU_DIR) + "/" + name + ".fmu";
}

void copyWithEntries(const std::string& source, const std::string& target,
                     const std::vector<ZipEntry>& entries)
{
    std::filesystem::copy_file(
        source, target, std::filesystem::copy_options::overwrite_existing);
    int code = 0;
    zip_t* z = zip_open(target.c_str(), 0, &code);
    if (!z)
        throw std::runtime_error("cannot open " + target);
    for (const ZipEntry& e : entries) {
        zip_source_t* data
            = zip_source_buffer(z, e.content.data(), e.content.size(), 0);
        const zip_int64_t index = data
            ? zip_file_add(z, e.name.c_str(), data, ZIP_FL_ENC_UTF_8)
            : -1;
        if (index < 0) {
            if (data)
                zip_source_free(data);
            zip_discard(z);
            throw std::runtime_error("cannot add " + e.name + " to " + target);
        }
        if (e.symlink) {
            const zip_uint32_t mode = S_IFLNK | 0777;
            zip_file_set_external_attributes(z,
                                             static_cast<zip_uint64_t>(index),
                                             0, ZIP_OPSYS_UNIX, mode << 16);
        }
    }
    if (zip_close(z) != 0) {
        zip_discard(z);
        throw std::runtime_error("cannot write " + target);
    }
}

PrivateTmpDir::PrivateTmpDir()
{
    const char* old = std::getenv("TMPDIR");
    hadPrevious_ = old != nullptr;
    if (old)
        previous_ = old;
    std::string pattern
        = (std::filesystem::temp_directory_path() / "fmuImportTest-XXXXXX")
              .string();
    if (!mkdtemp(pattern.data()))
        throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
    setenv("TMPDIR", path_.c_str(), 1);
}

PrivateTmpDir::~PrivateTmpDir()
{
    if (hadPrevious_)
        setenv("TMPDIR", previous_.c_str(), 1);
    else
        unsetenv("TMPDIR");
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
}

std::vector<std::string> PrivateTmpDir::contents() const
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_))
        names.push_back(entry.path().filename());
    return names;
}

} // namespace fixtures

namespace fixtures {

void writeArchive(const std::string& target,
                  const std::vector<ZipEntry>& entries)
{
    std::filesystem::remove(target);
    int code = 0;
    zip_t* z = zip_open(target.c_str(), ZIP_CREATE | ZIP_EXCL, &code);
    if (!z)
        throw std::runtime_error("cannot create " + target);
    for (const ZipEntry& e : entries) {
        zip_source_t* data
            = zip_source_buffer(z, e.content.data(), e.content.size(), 0);
        if (!data
            || zip_file_add(z, e.name.c_str(), data, ZIP_FL_ENC_UTF_8) < 0) {
            if (data)
                zip_source_free(data);
            zip_discard(z);
            throw std::runtime_error("cannot add " + e.name + " to " + target);
        }
    }
    if (zip_close(z) != 0) {
        zip_discard(z);
        throw std::runtime_error("cannot write " + target);
    }
}

namespace {

struct Zeros {
    std::uint64_t size, offset = 0;
};

zip_int64_t zeroSource(void* userdata, void* data, zip_uint64_t length,
                       zip_source_cmd_t cmd)
{
    Zeros& z = *static_cast<Zeros*>(userdata);
    switch (cmd) {
    case ZIP_SOURCE_OPEN:
        z.offset = 0;
        return 0;
    case ZIP_SOURCE_READ: {
        const zip_uint64_t n
            = std::min<zip_uint64_t>(length, z.size - z.offset);
        std::memset(data, 0, n);
        z.offset += n;
        return static_cast<zip_int64_t>(n);
    }
    case ZIP_SOURCE_CLOSE:
        return 0;
    case ZIP_SOURCE_STAT: {
        zip_stat_t* st = static_cast<zip_stat_t*>(data);
        zip_stat_init(st);
        st->size = z.size;
        st->valid |= ZIP_STAT_SIZE;
        return sizeof(zip_stat_t);
    }
    case ZIP_SOURCE_FREE:
        delete &z;
        return 0;
    case ZIP_SOURCE_ERROR:
        std::memset(data, 0, 2 * sizeof(int));
        return 2 * sizeof(int);
    case ZIP_SOURCE_SUPPORTS:
        return zip_source_make_command_bitmap(
            ZIP_SOURCE_OPEN, ZIP_SOURCE_READ, ZIP_SOURCE_CLOSE, ZIP_SOURCE_STAT,
            ZIP_SOURCE_FREE, ZIP_SOURCE_ERROR, -1);
    default:
        return -1;
    }
}

std::uint32_t readLe32(const std::string& s, std::size_t at)
{
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = (v << 8) | static_cast<unsigned char>(s[at + i]);
    return v;
}

void writeLe32(std::string& s, std::size_t at, std::uint32_t v)
{
    for (int i = 0; i < 4; ++i)
        s[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
}

} // namespace

void addZeroEntry(const std::string& path, const std::string& name,
                  std::uint64_t size)
{
    int code = 0;
    zip_t* z = zip_open(path.c_str(), 0, &code);
    if (!z)
        throw std::runtime_error("cannot open " + path);
    zip_source_t* data = zip_source_function(z, zeroSource, new Zeros {size});
    if (!data || zip_file_add(z, name.c_str(), data, ZIP_FL_ENC_UTF_8) < 0
        || zip_close(z) != 0) {
        zip_discard(z);
        throw std::runtime_error("cannot add " + name + " to " + path);
    }
}

namespace {

// Calls patch(bytes, header, central) for the local header and the central
// directory entry of the entry name in the archive at path (header: the
// offset of the header, central: whether it is the directory's), then
// writes the bytes back; both must be found.
template <class Patch>
void patchHeaders(const std::string& path, const std::string& name, Patch patch)
{
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        bytes = s.str();
    }
    int patched = 0;
    for (std::size_t at = 0; at + 46 <= bytes.size(); ++at) {
        const std::uint32_t signature = readLe32(bytes, at);
        const bool local = signature == 0x04034b50u
            && bytes.compare(at + 30, name.size(), name) == 0;
        const bool central = signature == 0x02014b50u
            && bytes.compare(at + 46, name.size(), name) == 0;
        if (local || central) {
            patch(bytes, at, central);
            ++patched;
        }
    }
    if (patched != 2)
        throw std::runtime_error("cannot find both headers of " + name + " in "
                                 + path);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

} // namespace

void patchDeclaredSize(const std::string& path, const std::string& name,
                       std::uint32_t size)
{
    patchHeaders(path, name,
                 [size](std::string& bytes, std::size_t at, bool central) {
                     writeLe32(bytes, at + (central ? 24 : 22), size);
                 });
}

void renameEntry(const std::string& path, const std::string& from,
                 const std::string& to)
{
    if (from.size() != to.size())
        throw std::runtime_error("renameEntry: '" + from + "' and '" + to
                                 + "' differ in length");
    patchHeaders(path, from,
                 [&to](std::string& bytes, std::size_t at, bool central) {
                     bytes.replace(at + (central ? 46 : 30), to.size(), to);
                 });
}

ScopedEnv::ScopedEnv(const std::string& name, const std::string& value)
    : name_(name)
{
    const char* old = std::getenv(name.c_str());
    hadPrevious_ = old != nullptr;
    if (old)
        previous_ = old;
    setenv(name.c_str(), value.c_str(), 1);
}

ScopedEnv::~ScopedEnv()
{
    if (hadPrevious_)
        setenv(name_.c_str(), previous_.c_str(), 1);
    else
        unsetenv(name_.c_str());
}

FileSizeLimit::FileSizeLimit(std::uint64_t bytes)
{
    rlimit limit;
    getrlimit(RLIMIT_FSIZE, &limit);
    previous_ = limit.rlim_cur;
    limit.rlim_cur = bytes;
    previousHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    setrlimit(RLIMIT_FSIZE, &limit);
}

FileSizeLimit::~FileSizeLimit()
{
    rlimit limit;
    getrlimit(RLIMIT_FSIZE, &limit);
    limit.rlim_cur = previous_;
    setrlimit(RLIMIT_FSIZE, &limit);
    std::signal(SIGXFSZ, previousHandler_);
}

} // namespace fixtures

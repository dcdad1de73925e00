#include "Unzip.hpp"

#include "fmuImport/fmuImport.hpp"

#include <sys/stat.h>
#include <zip.h>

#include <fstream>
#include <memory>
#include <vector>

namespace fmuImport {

namespace {

struct ArchiveCloser
{
    void operator()(zip_t* z) const { zip_discard(z); }
};

struct EntryCloser
{
    void operator()(zip_file_t* f) const { zip_fclose(f); }
};

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// The entry's name as a relative path, or an Error for one that could
// escape the target directory.
std::filesystem::path safeRelativePath(const std::string& archive, const std::string& name)
{
    const std::string where = "FMU " + quoted(archive) + ": archive entry " + quoted(name);
    if (name.empty() || name.front() == '/') throw Error(where + " has an absolute path");
    if (name.find('\\') != std::string::npos) throw Error(where + " contains a backslash");
    const std::filesystem::path path(name);
    for (const auto& part : path)
    {
        if (part == "..") throw Error(where + " has a '..' component");
    }
    return path.lexically_normal();
}

bool isSymlink(zip_t* z, zip_uint64_t index)
{
    zip_uint8_t system = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(z, index, 0, &system, &attributes) != 0) return false;
    return system == ZIP_OPSYS_UNIX && S_ISLNK(attributes >> 16);
}

}  // namespace

void unzip(const std::string& archive, const std::filesystem::path& directory)
{
    int code = 0;
    std::unique_ptr<zip_t, ArchiveCloser> z(zip_open(archive.c_str(), ZIP_RDONLY, &code));
    if (!z)
    {
        zip_error_t error;
        zip_error_init_with_code(&error, code);
        const std::string reason = zip_error_strerror(&error);
        zip_error_fini(&error);
        throw Error("FMU " + quoted(archive) + " cannot be opened as a zip archive: " + reason);
    }

    const zip_int64_t n = zip_get_num_entries(z.get(), 0);
    std::vector<char> buffer(1 << 16);
    for (zip_int64_t i = 0; i < n; ++i)
    {
        const char* rawName = zip_get_name(z.get(), i, ZIP_FL_ENC_GUESS);
        const std::string name = rawName ? rawName : "";
        const std::filesystem::path relative = safeRelativePath(archive, name);
        if (isSymlink(z.get(), i))
            throw Error("FMU " + quoted(archive) + ": archive entry " + quoted(name) + " is a symbolic link");

        const std::filesystem::path target = directory / relative;
        std::error_code ec;
        if (name.back() == '/')
        {
            std::filesystem::create_directories(target, ec);
            if (ec)
                throw Error("FMU " + quoted(archive) + ": cannot create " + quoted(target.string()) + ": " +
                            ec.message());
            continue;
        }
        std::filesystem::create_directories(target.parent_path(), ec);
        if (ec)
            throw Error("FMU " + quoted(archive) + ": cannot create " + quoted(target.parent_path().string()) + ": " +
                        ec.message());

        std::unique_ptr<zip_file_t, EntryCloser> entry(zip_fopen_index(z.get(), i, 0));
        if (!entry)
            throw Error("FMU " + quoted(archive) + ": cannot read archive entry " + quoted(name) + ": " +
                        zip_strerror(z.get()));
        std::ofstream out(target, std::ios::binary);
        if (!out) throw Error("FMU " + quoted(archive) + ": cannot write " + quoted(target.string()));
        zip_int64_t got = 0;
        while ((got = zip_fread(entry.get(), buffer.data(), buffer.size())) > 0) out.write(buffer.data(), got);
        if (got < 0)
            throw Error("FMU " + quoted(archive) + ": archive entry " + quoted(name) +
                        " is corrupt: " + zip_file_strerror(entry.get()));
        if (!out) throw Error("FMU " + quoted(archive) + ": cannot write " + quoted(target.string()));
    }
}

}  // namespace fmuImport

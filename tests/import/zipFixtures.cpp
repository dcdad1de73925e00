#include "zipFixtures.hpp"

#include <sys/stat.h>
#include <zip.h>

#include <cstdlib>
#include <stdexcept>

namespace fixtures {

std::string fmuPath(const std::string& name) { return std::string(FIXTURE_FMU_DIR) + "/" + name + ".fmu"; }

void copyWithEntries(const std::string& source, const std::string& target, const std::vector<ZipEntry>& entries)
{
    std::filesystem::copy_file(source, target, std::filesystem::copy_options::overwrite_existing);
    int code = 0;
    zip_t* z = zip_open(target.c_str(), 0, &code);
    if (!z) throw std::runtime_error("cannot open " + target);
    for (const ZipEntry& e : entries)
    {
        zip_source_t* data = zip_source_buffer(z, e.content.data(), e.content.size(), 0);
        const zip_int64_t index = data ? zip_file_add(z, e.name.c_str(), data, ZIP_FL_ENC_UTF_8) : -1;
        if (index < 0)
        {
            if (data) zip_source_free(data);
            zip_discard(z);
            throw std::runtime_error("cannot add " + e.name + " to " + target);
        }
        if (e.symlink)
        {
            const zip_uint32_t mode = S_IFLNK | 0777;
            zip_file_set_external_attributes(z, static_cast<zip_uint64_t>(index), 0, ZIP_OPSYS_UNIX, mode << 16);
        }
    }
    if (zip_close(z) != 0)
    {
        zip_discard(z);
        throw std::runtime_error("cannot write " + target);
    }
}

PrivateTmpDir::PrivateTmpDir()
{
    const char* old = std::getenv("TMPDIR");
    hadPrevious_ = old != nullptr;
    if (old) previous_ = old;
    std::string pattern = (std::filesystem::temp_directory_path() / "fmuImportTest-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
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
    for (const auto& entry : std::filesystem::directory_iterator(path_)) names.push_back(entry.path().filename());
    return names;
}

}  // namespace fixtures

#include "FmuImpl.hpp"
#include "ModelDescriptionXml.hpp"
#include "Unzip.hpp"

#include <sys/stat.h>

#include <cctype>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <mutex>
#include <tuple>
#include <system_error>

namespace fmuImport {

namespace {

std::string fileUri(const std::filesystem::path& path)
{
    static const char* const hex = "0123456789ABCDEF";
    std::string uri = "file://";
    for (const unsigned char c : path.string()) {
        if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.'
            || c == '~') {
            uri += static_cast<char>(c);
        } else {
            uri += '%';
            uri += hex[c >> 4];
            uri += hex[c & 15];
        }
    }
    return uri;
}

// Identifies a file's current content well enough to share its unpacked
// copy: a rewritten .fmu gets a new size or modification time.
struct FileKey {
    std::string canonicalPath;
    dev_t device;
    ino_t inode;
    off_t size;
    std::int64_t mtimeNs;

    bool operator<(const FileKey& o) const
    {
        return std::tie(canonicalPath, device, inode, size, mtimeNs)
            < std::tie(o.canonicalPath, o.device, o.inode, o.size, o.mtimeNs);
    }
};

// Weak references: an entry keeps nothing alive, and an expired one is
// dropped at the next load.
std::mutex cacheMutex;
std::map<FileKey, std::weak_ptr<Fmu::Impl>> cache;

} // namespace

std::shared_ptr<Fmu::Impl> Fmu::Impl::load(const std::string& fmuPath)
{
    struct stat st;
    std::error_code ec;
    const std::filesystem::path canonical
        = std::filesystem::canonical(fmuPath, ec);
    if (ec || stat(canonical.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        throw Error("FMU '" + fmuPath + "' does not exist or is not a file");
    const FileKey key {canonical.string(), st.st_dev, st.st_ino, st.st_size,
                       std::int64_t(st.st_mtim.tv_sec) * 1000000000
                           + st.st_mtim.tv_nsec};

    // Held while loading, so that two threads loading one file share it.
    const std::lock_guard<std::mutex> lock(cacheMutex);
    for (auto it = cache.begin(); it != cache.end();)
        it = it->second.expired() ? cache.erase(it) : std::next(it);
    if (const auto found = cache.find(key); found != cache.end()) {
        if (std::shared_ptr<Impl> shared = found->second.lock())
            return shared;
    }
    auto impl = std::make_shared<Impl>(fmuPath);
    cache[key] = impl;
    return impl;
}

Fmu::Impl::Impl(const std::string& fmuPath) : path(fmuPath)
{
    FmuArchive archive(fmuPath, UnpackLimits::fromEnvironment());

    // The description first, from memory: it names the binary to unpack.
    const std::string xmlName = "modelDescription.xml";
    if (!archive.has(xmlName))
        throw Error("FMU '" + fmuPath + "' has no modelDescription.xml");
    const std::string xml = archive.read(xmlName);
    description = readModelDescription(xml, fmuPath);
    indexVariables();
    const std::string binary = binaryEntry(description);
    if (!archive.has(binary))
        throw Error("FMU '" + fmuPath + "' has no binary " + binary);

    directory.emplace();
    root = directory->path();
    archive.write(xmlName, xml, root);
    archive.extract(binary, "resources/", root);
}

Fmu Fmu::Impl::openUnpacked(const std::string& directory,
                            const std::string& fmuPath)
{
    std::shared_ptr<Impl> impl(new Impl);
    impl->path = fmuPath;
    impl->root = directory;
    std::ifstream in(impl->root / "modelDescription.xml", std::ios::binary);
    std::stringstream xml;
    xml << in.rdbuf();
    if (!in)
        throw Error("FMU '" + fmuPath
                    + "': cannot read modelDescription.xml in '" + directory
                    + "'");
    impl->description = readModelDescription(xml.str(), fmuPath);
    impl->indexVariables();
    impl->loadLibrary();
    return Fmu(impl, fmuPath);
}

void Fmu::Impl::indexVariables()
{
    for (std::size_t i = 0; i < description.variables.size(); ++i) {
        index.emplace(description.variables[i].name, i);
        if (description.fmiMajorVersion != 3)
            continue;
        const Variable& v = description.variables[i];
        byReference.emplace(v.valueReference, i);
        elementsOf[v.arrayValueReference].push_back(i);
    }
}

void Fmu::Impl::loadLibrary()
{
    const std::lock_guard<std::mutex> lock(libraryMutex_);
    if (!library_)
        library_ = std::make_unique<Library>(
            (root / binaryEntry(description)).string(), path,
            description.fmiMajorVersion);
}

std::string Fmu::Impl::resourceLocation() const
{
    return fileUri(root / "resources");
}

Fmu::Fmu(const std::string& fmuPath, const FmuOptions& options)
    : impl_(Impl::load(fmuPath)), path_(fmuPath), options_(options)
{
    if (options_.isolation == Isolation::none)
        impl_->loadLibrary();
}

Fmu::Fmu(std::shared_ptr<Impl> impl, const std::string& path)
    : impl_(std::move(impl)), path_(path)
{
}

Fmu::~Fmu() = default;
Fmu::Fmu(Fmu&&) noexcept = default;
Fmu& Fmu::operator=(Fmu&&) noexcept = default;

const std::string& Fmu::path() const
{
    return path_;
}

const FmuOptions& Fmu::options() const
{
    return options_;
}

const ModelDescription& Fmu::modelDescription() const
{
    return impl_->description;
}

bool Fmu::hasVariable(const std::string& name) const
{
    return impl_->index.count(name) != 0;
}

const Variable& Fmu::variable(const std::string& name) const
{
    const auto found = impl_->index.find(name);
    if (found == impl_->index.end())
        throw Error("FMU '" + path_ + "' has no variable '" + name + "'");
    return impl_->description.variables[found->second];
}

std::string Fmu::resourceLocation() const
{
    return impl_->resourceLocation();
}

std::string Fmu::unpackDirectory() const
{
    return impl_->root.string();
}

} // namespace fmuImport

#include "FmuImpl.hpp"
#include "ModelDescriptionXml.hpp"
#include "Unzip.hpp"

#include <cctype>
#include <system_error>

namespace fmuImport {

namespace {

std::string fileUri(const std::filesystem::path& path)
{
    static const char* const hex = "0123456789ABCDEF";
    std::string uri = "file://";
    for (const unsigned char c : path.string())
    {
        if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~')
        {
            uri += static_cast<char>(c);
        }
        else
        {
            uri += '%';
            uri += hex[c >> 4];
            uri += hex[c & 15];
        }
    }
    return uri;
}

}  // namespace

Fmu::Impl::Impl(const std::string& fmuPath) : path(fmuPath)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(fmuPath, ec))
        throw Error("FMU '" + fmuPath + "' does not exist or is not a file");
    FmuArchive archive(fmuPath, UnpackLimits::fromEnvironment());

    // The description first, from memory: it names the binary to unpack.
    const std::string xmlName = "modelDescription.xml";
    if (!archive.has(xmlName)) throw Error("FMU '" + fmuPath + "' has no modelDescription.xml");
    const std::string xml = archive.read(xmlName);
    description = readModelDescription(xml, fmuPath);
    for (std::size_t i = 0; i < description.variables.size(); ++i) index.emplace(description.variables[i].name, i);
    const std::string binary = "binaries/linux64/" + description.modelIdentifier + ".so";
    if (!archive.has(binary)) throw Error("FMU '" + fmuPath + "' has no binary " + binary);

    directory.emplace();
    archive.write(xmlName, xml, directory->path());
    archive.extract(binary, "resources/", directory->path());
    library = std::make_unique<Library>((directory->path() / binary).string(), fmuPath);
}

Fmu::Fmu(const std::string& fmuPath) : impl_(std::make_shared<Impl>(fmuPath)) {}

Fmu::~Fmu() = default;
Fmu::Fmu(Fmu&&) noexcept = default;
Fmu& Fmu::operator=(Fmu&&) noexcept = default;

const std::string& Fmu::path() const { return impl_->path; }

const ModelDescription& Fmu::modelDescription() const { return impl_->description; }

bool Fmu::hasVariable(const std::string& name) const { return impl_->index.count(name) != 0; }

const Variable& Fmu::variable(const std::string& name) const
{
    const auto found = impl_->index.find(name);
    if (found == impl_->index.end()) throw Error("FMU '" + impl_->path + "' has no variable '" + name + "'");
    return impl_->description.variables[found->second];
}

std::string Fmu::resourceLocation() const { return fileUri(impl_->directory->path() / "resources"); }

std::string Fmu::unpackDirectory() const { return impl_->directory->path().string(); }

}  // namespace fmuImport

#include "UnpackedFmu.hpp"

#include <stdexcept>

#include "FmuImpl.hpp"

namespace fmuTest {

UnpackedFmu::UnpackedFmu(const std::string& modelName, const std::string& path)
    : name(modelName), fmu_(std::make_shared<fmuImport::Fmu::Impl>(path))
{
    directory = fmu_->root;
    const std::string xml = (directory / "modelDescription.xml").string();
    if (!description.load_file(xml.c_str())) {
        throw std::runtime_error("cannot parse " + xml);
    }
}

UnpackedFmu::~UnpackedFmu() = default;

const fmuImport::ModelDescription& UnpackedFmu::modelDescription() const
{
    return fmu_->description;
}

const fmuImport::Library& UnpackedFmu::loadLibrary()
{
    fmu_->loadLibrary();
    return fmu_->library();
}

void* UnpackedFmu::symbol(const char* name) const
{
    return fmu_->library().symbol(name);
}

} // namespace fmuTest

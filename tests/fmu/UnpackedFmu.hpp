// What the FMI 2.0 and 3.0 test harnesses (FmuHarness.hpp, Fmi3Harness.hpp)
// share: an FMU unpacked by the importer (fmuImport::Fmu::Impl) into a
// directory of its own, not shared with another UnpackedFmu of the same
// file (each loads the binary anew), and its modelDescription.xml as
// written in the FMU and as the importer reads it.
#ifndef TESTS_FMU_UNPACKEDFMU_HPP
#define TESTS_FMU_UNPACKEDFMU_HPP

#include <pugixml.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "Library.hpp"
#include "fmuImport/fmuImport.hpp"

namespace fmuTest {

//- Not copyable (pugi::xml_document is not)
class UnpackedFmu {
public:
    //- The FMU at `path`, unpacked, its modelDescription.xml parsed (throws
    //  naming the file where it cannot); the model's name is `name`
    UnpackedFmu(const std::string& name, const std::string& path);
    ~UnpackedFmu();

    //- Functions the harness resolves besides the importer's API that the
    //  binary does not export (one of the importer's missing fails the load)
    std::vector<std::string> missing;
    std::string name;
    //- modelDescription.xml as written in the FMU
    pugi::xml_document description;
    std::filesystem::path directory;

    //- modelDescription.xml as the importer reads it
    const fmuImport::ModelDescription& modelDescription() const;

protected:
    //- The binary, loaded
    const fmuImport::Library& loadLibrary();

    //- f set to the function the loaded binary exports as `name`; `name`
    //  appended to `missing` where it exports none
    template <class Function> void resolve(const char* name, Function*& f)
    {
        f = reinterpret_cast<Function*>(symbol(name));
        if (f == nullptr) {
            missing.push_back(name);
        }
    }

private:
    void* symbol(const char* name) const;

    std::shared_ptr<fmuImport::Fmu::Impl> fmu_;
};

} // namespace fmuTest

#endif

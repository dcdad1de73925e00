// fmuGenerator <directory>: writes <directory>/modelDescription.xml and
// <directory>/documentation/index.html for the model it is linked with.
// fmuGenerator -fmi3 <directory>: the FMI 3.0 FMU's modelDescription.xml
// and terminalsAndIcons/terminalsAndIcons.xml.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "ModelDescription.hpp"

namespace {

void writeFile(const std::filesystem::path& path, const std::string& text)
{
    std::filesystem::create_directories(path.parent_path());
    std::ofstream file(path, std::ios::binary);
    file << text;
    if (!file) {
        throw std::runtime_error("cannot write " + path.string());
    }
}

} // namespace

int main(int argc, char** argv)
{
    const bool fmi3 = argc == 3 && std::string(argv[1]) == "-fmi3";
    if (argc != 2 && !fmi3) {
        std::cerr << "usage: " << argv[0] << " [-fmi3] <output directory>\n";
        return 2;
    }
    try {
        const std::unique_ptr<fmuExport::Model> model
            = fmuExport::createModel();
        const std::filesystem::path dir(argv[argc - 1]);
        if (fmi3) {
            writeFile(dir / "modelDescription.xml",
                      fmuExport::modelDescription3Xml(*model));
            writeFile(dir / "terminalsAndIcons" / "terminalsAndIcons.xml",
                      fmuExport::terminalsAndIconsXml(*model));
            return 0;
        }
        writeFile(dir / "modelDescription.xml",
                  fmuExport::modelDescriptionXml(*model));
        writeFile(dir / "documentation" / "index.html",
                  fmuExport::documentationHtml(*model));
    } catch (const std::exception& e) {
        std::cerr << argv[0] << ": " << e.what() << '\n';
        return 1;
    }
    return 0;
}

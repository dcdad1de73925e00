// fmuGenerator <directory>: writes <directory>/modelDescription.xml and
// <directory>/documentation/index.html for the model it is linked with.
#include <filesystem>
#include <fstream>
#include <iostream>

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
    if (argc != 2) {
        std::cerr << "usage: " << argv[0] << " <output directory>\n";
        return 2;
    }
    try {
        const std::unique_ptr<fmuExport::Model> model
            = fmuExport::createModel();
        const std::filesystem::path dir(argv[1]);
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

// Unpacking of an FMU archive with libzip.
#ifndef FMUIMPORT_UNZIP_HPP
#define FMUIMPORT_UNZIP_HPP

#include <filesystem>
#include <string>

namespace fmuImport {

// Extracts every entry of the zip archive at archive into directory.
// Refuses (Error naming the archive and the entry) absolute entry names,
// '..' components, backslashes and symbolic links.
void unzip(const std::string& archive, const std::filesystem::path& directory);

}  // namespace fmuImport

#endif

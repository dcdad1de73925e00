#include "TempDir.hpp"

#include "fmuImport/fmuImport.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace fmuImport {

TempDir::TempDir()
{
    std::error_code ec;
    std::filesystem::path base = std::filesystem::temp_directory_path(ec);
    if (ec) base = "/tmp";
    std::string pattern = (base / "fmuImport-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
        throw Error("cannot create a temporary directory from '" + pattern + "': " + std::strerror(errno));
    path_ = pattern;
}

TempDir::~TempDir()
{
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
}

}  // namespace fmuImport

// What an Fmu and its instances share: the unpacked files, the description
// and the loaded library. Members are destroyed in reverse order, so the
// library is closed before the directory is removed. The directory is made
// only once the archive and its description passed every check.
#ifndef FMUIMPORT_FMUIMPL_HPP
#define FMUIMPORT_FMUIMPL_HPP

#include "Library.hpp"
#include "TempDir.hpp"
#include "fmuImport/fmuImport.hpp"

#include <atomic>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace fmuImport {

struct Fmu::Impl {
    std::string path;
    std::optional<TempDir> directory;
    ModelDescription description;
    std::map<std::string, std::size_t>
        index; // variable name -> position in description.variables
    std::unique_ptr<Library> library;
    std::atomic<int> liveInstances {0}; // of every Fmu sharing this Impl

    explicit Impl(const std::string& fmuPath);

    // The Impl of the file at fmuPath: the one already loaded in this
    // process when the same file (canonical path, device, inode, size and
    // modification time) is still in use by an Fmu or Instance, else a new
    // one. So an FMU named by several restraints is unpacked and loaded once.
    static std::shared_ptr<Impl> load(const std::string& fmuPath);
};

} // namespace fmuImport

#endif

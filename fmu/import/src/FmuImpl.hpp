// What an Fmu and its instances share: the unpacked files, the description
// and the loaded library. Members are destroyed in reverse order, so the
// library is closed before the directory is removed. The directory is made
// only once the archive and its description passed every check. The
// library is loaded when an instance in this process needs it
// (Isolation::none): an Fmu whose instances run in child processes never
// loads it here.
#ifndef FMUIMPORT_FMUIMPL_HPP
#define FMUIMPORT_FMUIMPL_HPP

#include "Library.hpp"
#include "TempDir.hpp"
#include "fmuImport/fmuImport.hpp"

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

namespace fmuImport {

struct Fmu::Impl {
    std::string path;
    std::optional<TempDir> directory; // empty for an unpacked FMU (below)
    std::filesystem::path root; // where the files are
    ModelDescription description;
    std::map<std::string, std::size_t>
        index; // variable name -> position in description.variables
    // FMI 3.0: value reference (the importer's, one per element) ->
    // position in description.variables
    std::unordered_map<unsigned int, std::size_t> byReference;
    // FMI 3.0: an array's value reference -> its elements' positions in
    // description.variables, in element order
    std::unordered_map<unsigned int, std::vector<std::size_t>> elementsOf;
    std::atomic<int> liveInstances {0}; // of every Fmu sharing this Impl

    explicit Impl(const std::string& fmuPath);

    // Fills index and byReference from description
    void indexVariables();

    // The FMU another process unpacked in directory (an FMU's child
    // process): its description read from there, its binary loaded;
    // errors name fmuPath. Nothing is removed when it is gone.
    static Fmu openUnpacked(const std::string& directory,
                            const std::string& fmuPath);

    // Loads the binary if it is not loaded yet; Error naming the missing
    // fmi2 functions or dlopen's reason.
    void loadLibrary();

    // The loaded binary (after loadLibrary)
    const Library& library() const { return *library_; }

    // file:// URI of the resources folder
    std::string resourceLocation() const;

    // The Impl of the file at fmuPath: the one already loaded in this
    // process when the same file (canonical path, device, inode, size and
    // modification time) is still in use by an Fmu or Instance, else a new
    // one. So an FMU named by several restraints is unpacked and loaded once.
    static std::shared_ptr<Impl> load(const std::string& fmuPath);

private:
    Impl() = default;
    std::mutex libraryMutex_;
    std::unique_ptr<Library> library_;
};

} // namespace fmuImport

#endif

// libFuzzer target: an untrusted .fmu archive through fmuImport::Fmu, the
// unzip, limits and modelDescription.xml path. The input is written to a
// file, since the importer opens archives by path. fmuImport::Error is the
// expected way to refuse an input; anything else (another exception, a
// crash, a sanitizer report) is a finding.
//
// The seed archives (corpus/fmuArchive) hold stub binaries that are not
// ELF files: dlopen of a mutated real binary could crash inside the
// dynamic loader, which is not the importer's code.
#include "fmuImport/fmuImport.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

std::string archivePath;

extern "C" void removeArchive()
{
    unlink(archivePath.c_str());
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    // Keeps a hostile archive that passes every check from writing much.
    setenv("FMUIMPORT_MAX_UNPACK_BYTES", "4194304", 1);
    const char* tmp = std::getenv("TMPDIR");
    archivePath = std::string(tmp && *tmp ? tmp : "/tmp") + "/fuzzFmuArchive-"
        + std::to_string(getpid()) + ".fmu";
    std::atexit(removeArchive);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size)
{
    {
        std::ofstream out(archivePath, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data),
                  static_cast<std::streamsize>(size));
    }
    try {
        const fmuImport::Fmu fmu(archivePath);
        for (const fmuImport::Variable& v : fmu.modelDescription().variables)
            (void)fmu.variable(v.name);
        (void)fmu.resourceLocation();
    } catch (const fmuImport::Error&) {
    }
    return 0;
}

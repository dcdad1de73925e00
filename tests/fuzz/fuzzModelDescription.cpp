// libFuzzer target: the modelDescription.xml parser on untrusted bytes.
// fmuImport::Error is the expected way to refuse an input; anything else
// (another exception, a crash, a sanitizer report) is a finding.
#include "ModelDescriptionXml.hpp"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size)
{
    try {
        const fmuImport::ModelDescription md = fmuImport::readModelDescription(
            std::string(reinterpret_cast<const char*>(data), size), "fuzz.fmu");
        (void)md;
    } catch (const fmuImport::Error&) {
    }
    return 0;
}

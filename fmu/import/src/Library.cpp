#include "Library.hpp"

#include "FpTraps.hpp"
#include "fmuImport/fmuImport.hpp"

#include <dlfcn.h>

namespace fmuImport {

Library::Library(const std::string& file, const std::string& fmuPath)
{
    handle_ = callFmu(dlopen, file.c_str(),
                      RTLD_LOCAL | RTLD_NOW); // runs the FMU's constructors
    if (!handle_) {
        const char* reason = dlerror();
        throw Error("FMU '" + fmuPath
                    + "': cannot load its binary: " + (reason ? reason : file));
    }
    std::string missing;
#define FMUIMPORT_RESOLVE(name)                                                \
    api_.name                                                                  \
        = reinterpret_cast<fmi2##name##TYPE*>(dlsym(handle_, "fmi2" #name));   \
    if (!api_.name)                                                            \
        missing += std::string(missing.empty() ? "" : ", ") + "fmi2" #name;
    FMUIMPORT_FMI2_FUNCTIONS(FMUIMPORT_RESOLVE)
#undef FMUIMPORT_RESOLVE
    if (!missing.empty()) {
        callFmu(dlclose, handle_);
        throw Error("FMU '" + fmuPath + "': its binary does not export "
                    + missing);
    }
}

Library::~Library()
{
    callFmu(dlclose, handle_);
} // runs the FMU's destructors

} // namespace fmuImport

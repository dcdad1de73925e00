#include "Library.hpp"

#include "FpTraps.hpp"
#include "fmuImport/fmuImport.hpp"

#include <dlfcn.h>

namespace fmuImport {

Library::Library(const std::string& file, const std::string& fmuPath,
                 int fmiMajorVersion)
{
    handle_ = callFmu(dlopen, file.c_str(),
                      RTLD_LOCAL | RTLD_NOW); // runs the FMU's constructors
    if (!handle_) {
        const char* reason = dlerror();
        throw Error("FMU '" + fmuPath
                    + "': cannot load its binary: " + (reason ? reason : file));
    }
    std::string missing;
#define FMUIMPORT_RESOLVE(api, v, name)                                        \
    api.name = reinterpret_cast<fmi##v##name##TYPE*>(                          \
        dlsym(handle_, "fmi" #v #name));                                       \
    if (!api.name)                                                             \
        missing += std::string(missing.empty() ? "" : ", ") + "fmi" #v #name;
#define FMUIMPORT_RESOLVE2(name) FMUIMPORT_RESOLVE(api_, 2, name)
#define FMUIMPORT_RESOLVE3(name) FMUIMPORT_RESOLVE(api3_, 3, name)
    if (fmiMajorVersion == 3) {
        FMUIMPORT_FMI3_FUNCTIONS(FMUIMPORT_RESOLVE3)
    } else {
        FMUIMPORT_FMI2_FUNCTIONS(FMUIMPORT_RESOLVE2)
    }
#undef FMUIMPORT_RESOLVE3
#undef FMUIMPORT_RESOLVE2
#undef FMUIMPORT_RESOLVE
    if (!missing.empty()) {
        callFmu(dlclose, handle_);
        throw Error("FMU '" + fmuPath + "': its binary does not export "
                    + missing);
    }
}

void* Library::symbol(const char* name) const
{
    return dlsym(handle_, name);
}

Library::~Library()
{
    callFmu(dlclose, handle_);
} // runs the FMU's destructors

} // namespace fmuImport

// Where the helper program fmuImportWorker is (ChildInstance.hpp)
#include "ChildInstance.hpp"

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>

namespace fmuImport {

namespace {

const char* const workerName = "fmuImportWorker";

bool isProgram(const std::string& path)
{
    struct stat st;
    return !path.empty() && stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)
        && access(path.c_str(), X_OK) == 0;
}

std::string folderOf(const std::string& path)
{
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

} // namespace

std::string workerProgram()
{
    if (const char* given = std::getenv("FMUIMPORT_WORKER")) {
        if (!isProgram(given))
            throw Error(std::string("the environment variable FMUIMPORT_WORKER "
                                    "names '")
                        + given + "', which is not an executable file");
        return given;
    }
    std::vector<std::string> candidates;
    char self[4096];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n > 0)
        candidates.push_back(folderOf(std::string(self, n)) + "/" + workerName);
    Dl_info info;
    if (dladdr(reinterpret_cast<void*>(&workerProgram), &info)
        && info.dli_fname) {
        const std::string folder = folderOf(info.dli_fname);
        candidates.push_back(folder + "/" + workerName);
        candidates.push_back(folder + "/../bin/" + workerName);
    }
#ifdef FMUIMPORT_WORKER_PATH
    candidates.push_back(FMUIMPORT_WORKER_PATH);
#endif
    for (const std::string& c : candidates)
        if (isProgram(c))
            return c;
    const char* path = std::getenv("PATH");
    for (std::string rest = path ? path : ""; !rest.empty();) {
        const std::size_t colon = rest.find(':');
        const std::string folder = rest.substr(0, colon);
        rest = colon == std::string::npos ? "" : rest.substr(colon + 1);
        if (isProgram(folder + "/" + workerName))
            return folder + "/" + workerName;
    }
    std::string tried;
    for (const std::string& c : candidates)
        tried += (tried.empty() ? "" : ", ") + c;
    throw Error(std::string("the helper program ") + workerName
                + " that runs an FMU in a process of its own was not found ("
                + tried
                + ", nor on PATH): build it with the project, or set the "
                  "environment variable FMUIMPORT_WORKER to it");
}

} // namespace fmuImport

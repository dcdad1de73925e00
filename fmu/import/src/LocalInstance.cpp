#include "InstanceImpl.hpp"

#include <cmath>
#include <sstream>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace fmuImport {

namespace {

const char* statusName(int status)
{
    static const char* const names[]
        = {"fmi2OK",    "fmi2Warning", "fmi2Discard",
           "fmi2Error", "fmi2Fatal",   "fmi2Pending"};
    return status >= 0 && status <= 5 ? names[status] : "unknown status";
}

std::string format(const char* text, va_list args)
{
    if (!text)
        return std::string();
    va_list sizing;
    va_copy(sizing, args);
    const int n = std::vsnprintf(nullptr, 0, text, sizing);
    va_end(sizing);
    if (n < 0)
        return text;
    std::vector<char> buffer(static_cast<std::size_t>(n) + 1);
    std::vsnprintf(buffer.data(), buffer.size(), text, args);
    return std::string(buffer.data(), static_cast<std::size_t>(n));
}

extern "C" void fmuImportLogger(fmi2ComponentEnvironment environment,
                                fmi2String instanceName, fmi2Status status,
                                fmi2String category, fmi2String message, ...)
{
    va_list args;
    va_start(args, message);
    const std::string text = format(message, args);
    va_end(args);
    try {
        static_cast<Instance::Impl*>(environment)
            ->receive(instanceName ? instanceName : "", status,
                      category ? category : "", text);
    } catch (...) {
        // An exception must not cross the FMU's C frames; the message is lost.
    }
}

} // namespace

Instance::Impl::Impl(std::shared_ptr<Fmu::Impl> fmuImpl,
                     const std::string& path, const std::string& instanceName,
                     Logger log)
    : fmu(std::move(fmuImpl)), fmuPath(path), name(instanceName),
      logger(std::move(log))
{
    callbacks.logger = fmuImportLogger;
    callbacks.allocateMemory = std::calloc;
    callbacks.freeMemory = std::free;
    callbacks.stepFinished = nullptr;
    callbacks.componentEnvironment = this;
}

Instance::Impl::~Impl()
{
    if (component)
        callFmu(api().FreeInstance, component);
    if (admitted)
        --fmu->liveInstances;
}

void Instance::Impl::admit()
{
    const int others = fmu->liveInstances++;
    admitted = true;
    if (others > 0 && fmu->description.canBeInstantiatedOnlyOncePerProcess) {
        throw Error(
            "FMU '" + fmuPath
            + "' declares canBeInstantiatedOnlyOncePerProcess=\"true\" and an instance "
            + "of it exists already: cannot instantiate '" + name
            + "' (free the other instance first)");
    }
}

void Instance::Impl::receive(const std::string& instanceName, int status,
                             const std::string& category,
                             const std::string& message)
{
    if (status >= fmi2Error)
        lastError = message;
    if (status >= fmi2Warning)
        lastNotice = message;
    if (logger) {
        logger(instanceName, status, category, message);
        return;
    }
    std::cerr << "[" << instanceName << "] " << statusName(status) << " "
              << category << ": " << message << '\n';
}

void Instance::Impl::check(fmi2Status status, const char* function, double time)
{
    if (status == fmi2OK)
        return;
    std::string detail;
    if (!std::isnan(time)) {
        std::ostringstream s;
        s.precision(17);
        s << " at t = " << time;
        detail = s.str();
    }
    if (status == fmi2Warning) {
        receive(name, fmi2Warning, "logStatusWarning",
                std::string(function) + " returned fmi2Warning" + detail);
        return;
    }
    std::string message = std::string(function) + " failed" + detail
        + " in FMU '" + fmuPath + "', instance '" + name + "' ("
        + statusName(status) + ")";
    if (!lastError.empty())
        message += ": " + lastError;
    throw Error(message);
}

} // namespace fmuImport

// The FMI calls of ChildInstance: each one a request to the child
// (Protocol.hpp), answered at once, or, once initialization is over, sent
// with the next request that returns something when it changes nothing
// but the FMU's state.
#include "ChildInstance.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

namespace fmuImport {

using protocol::FrameReader;
using protocol::Op;

template <class T>
void ChildInstance::setValues(Op op, const std::vector<unsigned int>& vrs,
                              const std::vector<T>& values)
{
    request(op, time, !deferred()).put(vrs).put(values).finish();
    if (!deferred())
        exchange();
}

FrameReader ChildInstance::getValues(Op op,
                                     const std::vector<unsigned int>& vrs)
{
    request(op, time, true).put(vrs).finish();
    return exchange();
}

void ChildInstance::setupExperiment(double startTime, bool stopTimeDefined,
                                    double stopTime)
{
    request(Op::setupExperiment, startTime, true)
        .put(startTime)
        .put(std::uint8_t(stopTimeDefined))
        .put(stopTime)
        .finish();
    exchange();
}

void ChildInstance::enterInitializationMode()
{
    request(Op::enterInitializationMode, time, true).finish();
    exchange();
}

void ChildInstance::exitInitializationMode()
{
    request(Op::exitInitializationMode, time, true).finish();
    exchange();
    initialized_ = true;
}

void ChildInstance::terminate()
{
    request(Op::terminate, time, true).finish();
    exchange();
}

void ChildInstance::reset()
{
    initialized_ = false;
    request(Op::reset, time, true).finish();
    exchange();
}

void ChildInstance::setReal(const std::vector<unsigned int>& vrs,
                            const std::vector<double>& values)
{
    setValues(Op::setReal, vrs, values);
}

void ChildInstance::getReal(const std::vector<unsigned int>& vrs,
                            double* values)
{
    const auto copy = [&](const std::vector<double>& got) {
        if (got.size() != vrs.size())
            throw Error("fmi2GetReal in the process of FMU '" + fmuPath
                        + "', instance '" + name
                        + "': " + std::to_string(got.size()) + " values for "
                        + std::to_string(vrs.size()) + " value references");
        std::copy(got.begin(), got.end(), values);
    };
    if (stepDone_) {
        const bool read = haveRead_ && vrs == readAfterStep_;
        stepDone_ = haveRead_ = false;
        if (read) {
            lastMessage_ = readMessage_;
            return copy(readValues_);
        }
        readAfterStep_ = vrs;
    }
    copy(getValues(Op::getReal, vrs).getVector<double>());
}

void ChildInstance::setInteger(const std::vector<unsigned int>& vrs,
                               const std::vector<int>& values)
{
    setValues(Op::setInteger, vrs, values);
}

std::vector<int> ChildInstance::getInteger(const std::vector<unsigned int>& vrs)
{
    return getValues(Op::getInteger, vrs).getVector<int>();
}

void ChildInstance::setBoolean(const std::vector<unsigned int>& vrs,
                               const std::vector<bool>& values)
{
    setValues(Op::setBoolean, vrs, values);
}

std::vector<bool>
ChildInstance::getBoolean(const std::vector<unsigned int>& vrs)
{
    return getValues(Op::getBoolean, vrs).getBools();
}

void ChildInstance::setString(const std::vector<unsigned int>& vrs,
                              const std::vector<std::string>& values)
{
    setValues(Op::setString, vrs, values);
}

std::vector<std::string>
ChildInstance::getString(const std::vector<unsigned int>& vrs)
{
    return getValues(Op::getString, vrs).getStrings();
}

Instance::StepResult
ChildInstance::doStep(double currentTime, double stepSize,
                      bool noSetFMUStatePriorToCurrentPoint, bool mayDiscard)
{
    request(Op::doStep, currentTime, true, currentTime + stepSize)
        .put(currentTime)
        .put(stepSize)
        .put(std::uint8_t(noSetFMUStatePriorToCurrentPoint))
        .put(std::uint8_t(mayDiscard))
        .put(readAfterStep_)
        .finish();
    FrameReader reply = exchange();
    const auto result
        = static_cast<Instance::StepResult>(reply.get<std::uint8_t>());
    haveRead_ = reply.get<std::uint8_t>() != 0;
    if (haveRead_) {
        readValues_ = reply.getVector<double>();
        readMessage_ = reply.getString();
    }
    stepDone_ = result == Instance::StepResult::completed;
    return result;
}

double ChildInstance::lastSuccessfulTime()
{
    request(Op::lastSuccessfulTime, time, true).finish();
    return exchange().get<double>();
}

// A state is a number the child knows it by, chosen here, so that saving
// one needs no reply; saved again under its number, the child overwrites it.
void* ChildInstance::getState(void* reuse)
{
    const std::uint64_t id = reuse
        ? std::uint64_t(reinterpret_cast<std::uintptr_t>(reuse))
        : ++nextState_;
    request(Op::getState, time, !deferred()).put(id).finish();
    if (!deferred())
        exchange();
    return reinterpret_cast<void*>(static_cast<std::uintptr_t>(id));
}

void ChildInstance::setState(void* state)
{
    request(Op::setState, time, !deferred())
        .put(std::uint64_t(reinterpret_cast<std::uintptr_t>(state)))
        .finish();
    if (!deferred())
        exchange();
}

void ChildInstance::freeState(void* state) noexcept
{
    if (lost_ || socket_ < 0)
        return;
    try {
        request(Op::freeState, time, false)
            .put(std::uint64_t(reinterpret_cast<std::uintptr_t>(state)))
            .finish();
    } catch (...) {
        // A state that cannot be freed in a child that is gone is gone
    }
}

std::vector<char> ChildInstance::serializeState(void* state)
{
    request(Op::serializeState, time, true)
        .put(std::uint64_t(reinterpret_cast<std::uintptr_t>(state)))
        .finish();
    return exchange().getVector<char>();
}

void* ChildInstance::deserializeState(const std::vector<char>& bytes)
{
    const std::uint64_t id = ++nextState_;
    request(Op::deserializeState, time, true).put(id).put(bytes).finish();
    exchange();
    return reinterpret_cast<void*>(static_cast<std::uintptr_t>(id));
}

} // namespace fmuImport

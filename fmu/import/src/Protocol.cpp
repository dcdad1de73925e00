#include "Protocol.hpp"

#include "fmuImport/fmuImport.hpp"

#include <sched.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>

namespace fmuImport {
namespace protocol {

const char* functionOf(Op op)
{
    switch (op) {
    case Op::load:
        return "dlopen";
    case Op::instantiate:
        return "fmi2Instantiate";
    case Op::setupExperiment:
        return "fmi2SetupExperiment";
    case Op::enterInitializationMode:
        return "fmi2EnterInitializationMode";
    case Op::exitInitializationMode:
        return "fmi2ExitInitializationMode";
    case Op::terminate:
        return "fmi2Terminate";
    case Op::reset:
        return "fmi2Reset";
    case Op::setReal:
        return "fmi2SetReal";
    case Op::getReal:
        return "fmi2GetReal";
    case Op::setInteger:
        return "fmi2SetInteger";
    case Op::getInteger:
        return "fmi2GetInteger";
    case Op::setBoolean:
        return "fmi2SetBoolean";
    case Op::getBoolean:
        return "fmi2GetBoolean";
    case Op::setString:
        return "fmi2SetString";
    case Op::getString:
        return "fmi2GetString";
    case Op::doStep:
        return "fmi2DoStep";
    case Op::lastSuccessfulTime:
        return "fmi2GetRealStatus";
    case Op::getState:
        return "fmi2GetFMUstate";
    case Op::setState:
        return "fmi2SetFMUstate";
    case Op::freeState:
        return "fmi2FreeFMUstate";
    case Op::serializeState:
        return "fmi2SerializeFMUstate";
    case Op::deserializeState:
        return "fmi2DeSerializeFMUstate";
    case Op::freeInstance:
        return "fmi2FreeInstance";
    }
    return "an fmi2 function";
}

const char* functionOf(Op op, int fmiMajorVersion)
{
    if (fmiMajorVersion != 3)
        return functionOf(op);
    switch (op) {
    case Op::instantiate:
        return "fmi3InstantiateCoSimulation";
    case Op::setupExperiment:
    case Op::enterInitializationMode:
        return "fmi3EnterInitializationMode";
    case Op::exitInitializationMode:
        return "fmi3ExitInitializationMode";
    case Op::terminate:
        return "fmi3Terminate";
    case Op::reset:
        return "fmi3Reset";
    case Op::setReal:
        return "fmi3SetFloat64";
    case Op::getReal:
        return "fmi3GetFloat64";
    case Op::setInteger:
        return "fmi3SetInt32";
    case Op::getInteger:
        return "fmi3GetInt32";
    case Op::setBoolean:
        return "fmi3SetBoolean";
    case Op::getBoolean:
        return "fmi3GetBoolean";
    case Op::setString:
        return "fmi3SetString";
    case Op::getString:
        return "fmi3GetString";
    case Op::doStep:
    case Op::lastSuccessfulTime:
        return "fmi3DoStep";
    case Op::getState:
        return "fmi3GetFMUState";
    case Op::setState:
        return "fmi3SetFMUState";
    case Op::freeState:
        return "fmi3FreeFMUState";
    case Op::serializeState:
        return "fmi3SerializeFMUState";
    case Op::deserializeState:
        return "fmi3DeserializeFMUState";
    case Op::freeInstance:
        return "fmi3FreeInstance";
    default:
        return functionOf(op);
    }
}

bool waitOnPage(const std::atomic<std::uint64_t>& counter, std::uint64_t value,
                int microseconds)
{
    using Clock = std::chrono::steady_clock;
    const Clock::time_point until
        = Clock::now() + std::chrono::microseconds(microseconds);
    while (counter.load(std::memory_order_acquire) < value) {
        if (Clock::now() > until)
            return false;
        sched_yield();
    }
    return true;
}

FrameWriter::FrameWriter(std::vector<char>& out) : out_(out), start_(out.size())
{
    put(std::uint32_t(0));
}

void FrameWriter::finish()
{
    const std::uint32_t size
        = static_cast<std::uint32_t>(out_.size() - start_ - sizeof size);
    std::memcpy(out_.data() + start_, &size, sizeof size);
}

FrameWriter& FrameWriter::put(const std::string& text)
{
    put(static_cast<std::uint64_t>(text.size()));
    out_.insert(out_.end(), text.begin(), text.end());
    return *this;
}

FrameWriter& FrameWriter::put(const std::vector<bool>& values)
{
    put(static_cast<std::uint64_t>(values.size()));
    for (const bool b : values)
        out_.push_back(b ? 1 : 0);
    return *this;
}

FrameWriter& FrameWriter::put(const std::vector<std::string>& values)
{
    put(static_cast<std::uint64_t>(values.size()));
    for (const std::string& s : values)
        put(s);
    return *this;
}

const char* FrameReader::take(std::uint64_t n)
{
    if (n > static_cast<std::uint64_t>(end_ - p_))
        throw Error("fmuImport: a message between an instance and its process "
                    "is shorter than its contents");
    const char* at = p_;
    p_ += n;
    return at;
}

std::string FrameReader::getString()
{
    const std::uint64_t n = get<std::uint64_t>();
    const char* at = take(n);
    return std::string(at, at + n);
}

std::vector<bool> FrameReader::getBools()
{
    const std::uint64_t n = get<std::uint64_t>();
    const char* at = take(n);
    return std::vector<bool>(at, at + n);
}

std::vector<std::string> FrameReader::getStrings()
{
    const std::uint64_t n = get<std::uint64_t>();
    std::vector<std::string> values;
    for (std::uint64_t i = 0; i < n; ++i)
        values.push_back(getString());
    return values;
}

long Inbox::fill(int fd)
{
    if (begin_ == end_)
        begin_ = end_ = 0;
    else if (begin_ > data_.size() / 2) {
        std::memmove(data_.data(), data_.data() + begin_, end_ - begin_);
        end_ -= begin_;
        begin_ = 0;
    }
    if (data_.size() - end_ < 65536)
        data_.resize(end_ + 65536);
    ssize_t n;
    do
        n = ::read(fd, data_.data() + end_, data_.size() - end_);
    while (n < 0 && errno == EINTR);
    if (n > 0)
        end_ += static_cast<std::size_t>(n);
    return static_cast<long>(n);
}

bool Inbox::next(FrameReader& frame)
{
    std::uint32_t size = 0;
    if (end_ - begin_ < sizeof size)
        return false;
    std::memcpy(&size, data_.data() + begin_, sizeof size);
    if (end_ - begin_ - sizeof size < size) {
        if (data_.size() - begin_ < sizeof size + size)
            data_.resize(begin_ + sizeof size + size);
        return false;
    }
    const char* body = data_.data() + begin_ + sizeof size;
    frame = FrameReader(body, body + size);
    begin_ += sizeof size + size;
    return true;
}

} // namespace protocol
} // namespace fmuImport

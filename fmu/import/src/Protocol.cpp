#include "Protocol.hpp"

#include "fmuImport/fmuImport.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdio>

namespace fmuImport {
namespace protocol {

namespace {

// The function each request calls, in FMI 2.0 and in FMI 3.0
struct OpFunctions {
    Op op;
    const char* fmi2;
    const char* fmi3;
};

const OpFunctions opFunctions[] = {
    {Op::load, "dlopen", "dlopen"},
    {Op::instantiate, "fmi2Instantiate", "fmi3InstantiateCoSimulation"},
    {Op::setupExperiment, "fmi2SetupExperiment", "fmi3EnterInitializationMode"},
    {Op::enterInitializationMode, "fmi2EnterInitializationMode",
     "fmi3EnterInitializationMode"},
    {Op::exitInitializationMode, "fmi2ExitInitializationMode",
     "fmi3ExitInitializationMode"},
    {Op::terminate, "fmi2Terminate", "fmi3Terminate"},
    {Op::reset, "fmi2Reset", "fmi3Reset"},
    {Op::setReal, "fmi2SetReal", "fmi3SetFloat64"},
    {Op::getReal, "fmi2GetReal", "fmi3GetFloat64"},
    {Op::setInteger, "fmi2SetInteger", "fmi3SetInt32"},
    {Op::getInteger, "fmi2GetInteger", "fmi3GetInt32"},
    {Op::setBoolean, "fmi2SetBoolean", "fmi3SetBoolean"},
    {Op::getBoolean, "fmi2GetBoolean", "fmi3GetBoolean"},
    {Op::setString, "fmi2SetString", "fmi3SetString"},
    {Op::getString, "fmi2GetString", "fmi3GetString"},
    {Op::doStep, "fmi2DoStep", "fmi3DoStep"},
    {Op::lastSuccessfulTime, "fmi2GetRealStatus", "fmi3DoStep"},
    {Op::getState, "fmi2GetFMUstate", "fmi3GetFMUState"},
    {Op::setState, "fmi2SetFMUstate", "fmi3SetFMUState"},
    {Op::freeState, "fmi2FreeFMUstate", "fmi3FreeFMUState"},
    {Op::serializeState, "fmi2SerializeFMUstate", "fmi3SerializeFMUState"},
    {Op::deserializeState, "fmi2DeSerializeFMUstate",
     "fmi3DeserializeFMUState"},
    {Op::freeInstance, "fmi2FreeInstance", "fmi3FreeInstance"},
};

const OpFunctions* functionsOf(Op op)
{
    for (const OpFunctions& f : opFunctions)
        if (f.op == op)
            return &f;
    return nullptr;
}

} // namespace

const char* functionOf(Op op)
{
    const OpFunctions* f = functionsOf(op);
    return f ? f->fmi2 : "an fmi2 function";
}

const char* functionOf(Op op, int fmiMajorVersion)
{
    const OpFunctions* f = functionsOf(op);
    if (fmiMajorVersion != 3 || !f)
        return functionOf(op);
    return f->fmi3;
}

FrameWriter::FrameWriter(std::vector<char>& out, std::uint64_t seq)
    : out_(out), start_(out.size())
{
    put(FrameHeader {frameMagic, 0, seq});
}

void FrameWriter::finish()
{
    const std::uint32_t size = static_cast<std::uint32_t>(
        out_.size() - start_ - sizeof(FrameHeader));
    std::memcpy(out_.data() + start_ + offsetof(FrameHeader, length), &size,
                sizeof size);
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

void Inbox::makeRoom(std::size_t n)
{
    if (begin_ == end_)
        begin_ = end_ = 0;
    else if (begin_ > data_.size() / 2) {
        std::memmove(data_.data(), data_.data() + begin_, end_ - begin_);
        end_ -= begin_;
        begin_ = 0;
    }
    if (data_.size() - end_ < n)
        data_.resize(end_ + n);
}

long Inbox::fill(int fd)
{
    makeRoom(65536);
    ssize_t n;
    do
        n = ::read(fd, data_.data() + end_, data_.size() - end_);
    while (n < 0 && errno == EINTR);
    if (n > 0)
        end_ += static_cast<std::size_t>(n);
    return static_cast<long>(n);
}

void Inbox::append(const char* bytes, std::size_t n)
{
    makeRoom(n);
    std::memcpy(data_.data() + end_, bytes, n);
    end_ += n;
}

bool Inbox::next(FrameReader& frame, std::uint64_t& seq)
{
    // The magic word is checked as soon as it is in: stray bytes shorter
    // than a header are named as such, not awaited as a frame's start
    FrameHeader header {};
    const std::size_t in = end_ - begin_;
    std::memcpy(&header, data_.data() + begin_, std::min(in, sizeof header));
    if (in >= sizeof header.magic && header.magic != frameMagic) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "carried stray bytes (%zu bytes that are not a message: "
                      "magic word 0x%08x where a message begins with 0x%08x)",
                      in, unsigned(header.magic), unsigned(frameMagic));
        throw Garbled(text);
    }
    if (in >= offsetof(FrameHeader, seq) && header.length > longestFrame)
        throw Garbled("carried stray bytes (a message of "
                      + std::to_string(header.length)
                      + " bytes, longer than any: at most "
                      + std::to_string(longestFrame) + ")");
    if (in < sizeof header)
        return false;
    if (in - sizeof header < header.length) {
        if (data_.size() - begin_ < sizeof header + header.length)
            data_.resize(begin_ + sizeof header + header.length);
        return false;
    }
    const char* body = data_.data() + begin_ + sizeof header;
    frame = FrameReader(body, body + header.length);
    seq = header.seq;
    begin_ += sizeof header + header.length;
    return true;
}

Garbled Inbox::cutShort() const
{
    FrameHeader header {0, 0, 0};
    std::memcpy(&header, data_.data() + begin_,
                std::min(pending(), sizeof header));
    return Garbled(
        "ended within a message (" + std::to_string(pending()) + " of its "
        + (pending() < sizeof header
               ? std::to_string(sizeof header) + "-byte header"
               : std::to_string(sizeof header + header.length) + " bytes")
        + ")");
}

} // namespace protocol
} // namespace fmuImport

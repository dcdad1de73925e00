#include "FmuState.hpp"

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace fmuExport {

namespace {

constexpr char magic[8] = {'F', 'O', 'A', 'M', 'F', 'M', 'I', '\0'};
constexpr std::uint32_t formatVersion = 1;
constexpr unsigned restorableStates
    = instantiated | initializationMode | stepComplete | terminated;

struct Header {
    char magic[8];
    std::uint32_t version;
    std::uint32_t state;
    char guid[48];
    double time;
    std::uint32_t outputsValid;
    std::uint32_t valueCount;
};
static_assert(std::is_trivially_copyable_v<Header>);

} // namespace

const char* stateName(ModelState state)
{
    switch (state) {
    case instantiated:
        return "instantiated";
    case initializationMode:
        return "initializationMode";
    case stepComplete:
        return "stepComplete";
    case terminated:
        return "terminated";
    case error:
        return "error";
    case fatal:
        return "fatal";
    }
    return "unknown";
}

std::string stateNames(unsigned mask)
{
    std::string out;
    for (unsigned bit = 1; bit <= fatal; bit <<= 1) {
        if (mask & bit) {
            out += (out.empty() ? "" : " or ")
                + std::string(stateName(ModelState(bit)));
        }
    }
    return out.empty() ? "none" : out;
}

std::size_t serializedSize(std::size_t valueCount, std::size_t internalCount)
{
    const std::size_t base = sizeof(Header) + valueCount * sizeof(double);
    return internalCount == 0
        ? base
        : base + sizeof(std::uint64_t) + internalCount * sizeof(double);
}

void serializeState(const SavedState& state, const std::string& guid,
                    char* buffer, std::size_t size)
{
    const std::size_t needed
        = serializedSize(state.values.size(), state.internal.size());
    if (size < needed) {
        throw UsageError("buffer of " + std::to_string(size)
                         + " bytes is too small, " + std::to_string(needed)
                         + " bytes needed (fmi2SerializedFMUstateSize)");
    }
    Header header {};
    std::memcpy(header.magic, magic, sizeof magic);
    header.version = formatVersion;
    header.state = state.state;
    std::strncpy(header.guid, guid.c_str(), sizeof header.guid - 1);
    header.time = state.time;
    header.outputsValid = state.outputsValid ? 1 : 0;
    header.valueCount = std::uint32_t(state.values.size());
    std::memcpy(buffer, &header, sizeof header);
    char* out = buffer + sizeof header;
    std::memcpy(out, state.values.data(), state.values.size() * sizeof(double));
    if (!state.internal.empty()) {
        out += state.values.size() * sizeof(double);
        const std::uint64_t count = state.internal.size();
        std::memcpy(out, &count, sizeof count);
        std::memcpy(out + sizeof count, state.internal.data(),
                    state.internal.size() * sizeof(double));
    }
}

SavedState deserializeState(const char* bytes, std::size_t size,
                            const std::string& guid, std::size_t valueCount)
{
    Header header {};
    if (bytes == nullptr || size < sizeof header) {
        throw UsageError("serialized state of " + std::to_string(size)
                         + " bytes is shorter than its header ("
                         + std::to_string(sizeof header) + " bytes)");
    }
    std::memcpy(&header, bytes, sizeof header);
    if (std::memcmp(header.magic, magic, sizeof magic) != 0) {
        throw UsageError("bytes are not a serialized state of this FMU "
                         "(magic \"FOAMFMI\" not found)");
    }
    if (header.version != formatVersion) {
        throw UsageError("serialized state has format version "
                         + std::to_string(header.version) + ", expected "
                         + std::to_string(formatVersion));
    }
    header.guid[sizeof header.guid - 1] = '\0';
    if (guid != header.guid) {
        throw UsageError("serialized state belongs to the FMU with GUID "
                         + std::string(header.guid) + ", not " + guid);
    }
    // Internal state: present when the bytes go on after the value array
    std::size_t internalCount = 0;
    const std::size_t base = serializedSize(valueCount);
    const std::string sizeText
        = "serialized state has " + std::to_string(size) + " bytes";
    if (header.valueCount != valueCount) {
        throw UsageError(sizeText + " of " + std::to_string(header.valueCount)
                         + " values, expected " + std::to_string(valueCount)
                         + " values");
    }
    if (size < base) {
        throw UsageError(sizeText + ", shorter than its value array ("
                         + std::to_string(base) + " bytes)");
    }
    if (size > base && size < base + sizeof(std::uint64_t)) {
        throw UsageError(sizeText + ", expected " + std::to_string(base)
                         + " without internal state, or at least "
                         + std::to_string(base + sizeof(std::uint64_t))
                         + " with one");
    }
    if (size >= base + sizeof(std::uint64_t)) {
        std::uint64_t count = 0;
        std::memcpy(&count, bytes + base, sizeof count);
        if (count > 0 && count < (std::uint64_t(1) << 40)) {
            internalCount = std::size_t(count);
        }
    }
    const std::size_t expected = serializedSize(valueCount, internalCount);
    if (size != expected) {
        throw UsageError("serialized state has " + std::to_string(size)
                         + " bytes, expected " + std::to_string(expected));
    }
    if ((header.state & restorableStates) == 0
        || (header.state & (header.state - 1)) != 0) {
        throw UsageError("serialized state has an invalid instance state "
                         + std::to_string(header.state));
    }
    SavedState state;
    state.state = ModelState(header.state);
    state.time = header.time;
    state.outputsValid = header.outputsValid != 0;
    state.values.resize(valueCount);
    std::memcpy(state.values.data(), bytes + sizeof header,
                valueCount * sizeof(double));
    state.internal.resize(internalCount);
    if (internalCount > 0) {
        std::memcpy(state.internal.data(), bytes + base + sizeof(std::uint64_t),
                    internalCount * sizeof(double));
    }
    return state;
}

} // namespace fmuExport

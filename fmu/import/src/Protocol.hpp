// What an instance in this process (ChildInstance) and its child process
// (the helper program fmuImportWorker) say to each other: frames, posted
// in the shared call page (Channel.hpp) or, when too long for it, sent on
// the socket, which also carries the FMU's log messages as they come.
//
// A frame is a header (a magic word, the length of the body, a sequence
// number), then the body. A request is its operation and a flag "reply
// wanted", then its arguments; its sequence number counts the requests.
// The child answers only requests that want a reply, with a frame of the
// same sequence number: the results, the FMU's last message and the
// instance's time, or the error of the request, or of an earlier request
// without reply that failed (the requests after that one are skipped until
// the next one that wants a reply). Log messages of the FMU come as frames
// of their own, numbered as the request that logged them, before the reply.
// The magic word, the length and the sequence number make bytes that an
// FMU writes to the socket, or a frame cut short, an error named as such
// (Garbled) instead of a misread.
//
// A step's request carries the value references of the Reals the parent
// read right after the previous step (none at first): after a completed
// step the child reads them too and sends them with the reply, so that the
// parent's fmi2GetReal after the step needs no round trip of its own (the
// values are those it would have got: nothing comes between the two
// calls). A failed read is not an error of the step: the parent then asks
// again.
//
// Both ends are the same program's build on the same machine: numbers are
// sent in their native form.
#ifndef FMUIMPORT_PROTOCOL_HPP
#define FMUIMPORT_PROTOCOL_HPP

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace fmuImport {
namespace protocol {

enum class Op : std::uint8_t {
    load, // the directory the FMU is unpacked in, the FMU's path
    instantiate,
    setupExperiment,
    enterInitializationMode,
    exitInitializationMode,
    terminate,
    reset,
    setReal,
    getReal,
    setInteger,
    getInteger,
    setBoolean,
    getBoolean,
    setString,
    getString,
    doStep,
    lastSuccessfulTime,
    getState,
    setState,
    freeState,
    serializeState,
    deserializeState,
    freeInstance
};

// The fmi2 function a request calls ("fmi2DoStep"; "dlopen" for load)
const char* functionOf(Op op);
// The same for an FMU of FMI fmiMajorVersion: "fmi3DoStep" for 3
const char* functionOf(Op op, int fmiMajorVersion);

enum class Kind : std::uint8_t { log, reply };

// The header of every frame
struct FrameHeader {
    std::uint32_t magic;
    std::uint32_t length; // of the body [bytes]
    std::uint64_t seq;
};
constexpr std::uint32_t frameMagic = 0x31554d46; // "FMU1" in memory
// Longer bodies are not frames of this protocol: bytes of something else
constexpr std::uint32_t longestFrame = 1u << 30;

// Bytes that are not what the protocol says: a frame with a wrong magic
// word or length, a stream that ends within a frame. what() says which,
// after "the channel": "carried stray bytes (...)".
struct Garbled : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Appends one frame to a buffer.
class FrameWriter {
public:
    FrameWriter(std::vector<char>& out, std::uint64_t seq);
    // Fills in the frame's length; call once, at the end.
    void finish();

    template <class T> FrameWriter& put(const T& value)
    {
        static_assert(std::is_trivially_copyable<T>::value, "raw value");
        const char* p = reinterpret_cast<const char*>(&value);
        out_.insert(out_.end(), p, p + sizeof value);
        return *this;
    }
    FrameWriter& put(const std::string& text);
    template <class T> FrameWriter& put(const std::vector<T>& values)
    {
        static_assert(std::is_trivially_copyable<T>::value, "raw values");
        put(static_cast<std::uint64_t>(values.size()));
        const char* p = reinterpret_cast<const char*>(values.data());
        out_.insert(out_.end(), p, p + values.size() * sizeof(T));
        return *this;
    }
    FrameWriter& put(const std::vector<bool>& values);
    FrameWriter& put(const std::vector<std::string>& values);

private:
    std::vector<char>& out_;
    std::size_t start_;
};

// Reads the body of one frame; a short frame throws Error.
class FrameReader {
public:
    FrameReader(const char* begin, const char* end) : p_(begin), end_(end) { }

    template <class T> T get()
    {
        static_assert(std::is_trivially_copyable<T>::value, "raw value");
        T value;
        std::memcpy(&value, take(sizeof value), sizeof value);
        return value;
    }
    std::string getString();
    template <class T> std::vector<T> getVector()
    {
        const std::uint64_t n = get<std::uint64_t>();
        std::vector<T> values(n);
        if (n)
            std::memcpy(values.data(), take(n * sizeof(T)), n * sizeof(T));
        return values;
    }
    std::vector<bool> getBools();
    std::vector<std::string> getStrings();

private:
    const char* take(std::uint64_t n);
    const char* p_;
    const char* end_;
};

// Frames read from a socket or copied from the call page. A frame is
// complete once all its bytes are in.
class Inbox {
public:
    // Reads what the socket holds, or, for a blocking socket, waits for
    // something. Returns the bytes read: 0 at the end of the stream, -1
    // when a non-blocking socket has nothing now (errno EAGAIN) or on an
    // error (errno).
    long fill(int fd);
    // Appends bytes that came another way (the call page).
    void append(const char* bytes, std::size_t n);
    // The next complete frame and its sequence number, if one is in; it
    // stays valid until the next call of fill, append or next. Garbled
    // when the bytes at hand are not a frame's header.
    bool next(FrameReader& frame, std::uint64_t& seq);
    // Bytes in that are not a complete frame: at the end of the stream,
    // a frame cut short
    std::size_t pending() const { return end_ - begin_; }
    // Garbled naming a stream that ended within the frame in
    Garbled cutShort() const;

private:
    // Room for n more bytes after those in
    void makeRoom(std::size_t n);
    std::vector<char> data_;
    std::size_t begin_ = 0, end_ = 0;
};

} // namespace protocol
} // namespace fmuImport

#endif

// What an instance in this process (ChildInstance) and its child process
// (the helper program fmuImportWorker) say to each other, over a stream
// socket, and the page of shared memory in which the child marks the
// request it is running.
//
// Frames: a 32-bit length, then the body. A request is its operation, a
// flag "reply wanted", its sequence number and its arguments. The child
// answers only requests that want a reply: with the results, the FMU's
// last message and the instance's time, or with the error of the request,
// or of an earlier request without reply that failed (the requests after
// that one are skipped until the next one that wants a reply). Log
// messages of the FMU come as frames of their own, before the reply of the
// call that logged them.
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

#include <atomic>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace fmuImport {
namespace protocol {

// The child's file descriptors: the socket and the page
constexpr int socketFd = 3;
constexpr int pageFd = 4;

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

// The request the child runs: started is its sequence number, set before
// the request runs; finished is set to it afterwards. A request is in
// progress while started > finished.
// While reading is set, the request in progress is a step's read of the
// outputs (below). The parent waits for finished on the page a few
// microseconds (waitOnPage) before it waits on the socket: the reply of a
// fast FMU then costs no sleep and wake-up of the parent.
struct CallPage {
    std::atomic<std::uint64_t> started {0};
    std::atomic<std::uint64_t> finished {0};
    std::atomic<std::uint32_t> reading {0};
};

// Reads counter until it reaches value, for at most the given
// microseconds; whether it did. It yields the processor between reads
// (sched_yield), so that on a machine with more processes than cores the
// child it waits for can run: a busy loop of pause instructions there
// took the child's time and made a call ten times slower.
bool waitOnPage(const std::atomic<std::uint64_t>& counter, std::uint64_t value,
                int microseconds);
static_assert(std::atomic<std::uint64_t>::is_always_lock_free,
              "the page is shared between processes");

// Appends one frame to a buffer.
class FrameWriter {
public:
    explicit FrameWriter(std::vector<char>& out);
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

// Frames read from a socket. A frame is complete once all its bytes are in.
class Inbox {
public:
    // Reads what the socket holds, or, for a blocking socket, waits for
    // something. Returns the bytes read: 0 at the end of the stream, -1
    // when a non-blocking socket has nothing now (errno EAGAIN) or on an
    // error (errno).
    long fill(int fd);
    // The next complete frame, if one is in; it stays valid until the
    // next call of fill or next.
    bool next(FrameReader& frame);

private:
    std::vector<char> data_;
    std::size_t begin_ = 0, end_ = 0;
};

} // namespace protocol
} // namespace fmuImport

#endif

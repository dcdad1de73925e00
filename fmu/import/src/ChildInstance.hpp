// An instance in a child process of its own (Isolation::process): the
// helper program fmuImportWorker, started with posix_spawn, loads the
// FMU's binary from this process's unpack directory and runs an in-process
// instance of it; this side posts it the calls in a shared page
// (Channel.hpp, Protocol.hpp; ChildExchange.cpp) and turns its death, a
// call that outlasts the time limit, or an FMU that writes to or closes
// the socket between the two, into LostCall.
//
// posix_spawn, not fork: the child is a fresh program, not a copy of the
// host. A forked copy of an OpenFOAM solver would share its MPI library's
// state (open fabric connections, registered memory, progress threads that
// fork does not copy), and a fork of a multithreaded process may only call
// async-signal-safe functions until exec. glibc's posix_spawn runs the
// exec in a vfork-like clone that copies no memory, whatever the host's
// size.
#ifndef FMUIMPORT_CHILDINSTANCE_HPP
#define FMUIMPORT_CHILDINSTANCE_HPP

#include "Channel.hpp"
#include "InstanceImpl.hpp"
#include "Protocol.hpp"

#include <sys/types.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace fmuImport {

// The helper program's path: the environment variable FMUIMPORT_WORKER,
// else fmuImportWorker beside the running program, beside or in ../bin of
// the shared library that holds this code, in the build tree, or on PATH.
// Error when it is nowhere.
std::string workerProgram();

class ChildInstance : public Instance::Impl {
public:
    // Starts the child, loads the FMU there and instantiates it; Error as
    // Instance's constructor documents, LostCall when the child dies.
    ChildInstance(std::shared_ptr<Fmu::Impl> fmu, const std::string& fmuPath,
                  const std::string& name, Logger logger, bool loggingOn,
                  const FmuOptions& options);
    // fmi2FreeInstance in the child, which then ends
    ~ChildInstance() override;

    void setupExperiment(double startTime, bool stopTimeDefined,
                         double stopTime) override;
    void enterInitializationMode() override;
    void exitInitializationMode() override;
    void terminate() override;
    void reset() override;
    void setReal(const std::vector<unsigned int>& vrs,
                 const std::vector<double>& values) override;
    void getReal(const std::vector<unsigned int>& vrs, double* values) override;
    void setInteger(const std::vector<unsigned int>& vrs,
                    const std::vector<int>& values) override;
    std::vector<int> getInteger(const std::vector<unsigned int>& vrs) override;
    void setBoolean(const std::vector<unsigned int>& vrs,
                    const std::vector<bool>& values) override;
    std::vector<bool> getBoolean(const std::vector<unsigned int>& vrs) override;
    void setString(const std::vector<unsigned int>& vrs,
                   const std::vector<std::string>& values) override;
    std::vector<std::string>
    getString(const std::vector<unsigned int>& vrs) override;
    Instance::StepResult doStep(double currentTime, double stepSize,
                                bool noSetFMUStatePriorToCurrentPoint,
                                bool mayDiscard) override;
    double lastSuccessfulTime() override;
    std::string lastMessage() const override { return lastMessage_; }
    void* getState(void* reuse) override;
    void setState(void* state) override;
    void freeState(void* state) noexcept override;
    std::vector<char> serializeState(void* state) override;
    void* deserializeState(const std::vector<char>& bytes) override;

private:
    // A request sent and not answered yet
    struct Sent {
        std::uint64_t seq;
        protocol::Op op;
        double time;
        double endTime; // of a step
    };

    // Starts a request of op at the communication point t (for reports;
    // a step's end, endTime, names its read of the outputs); the caller
    // puts its arguments and finishes the frame. A request without reply
    // waits in the queue for the next one with.
    protocol::FrameWriter request(protocol::Op op, double t, bool reply,
                                  double endTime
                                  = std::numeric_limits<double>::quiet_NaN());

    // Posts the queue and returns the reply of its last request, after
    // the ok flag and the FMU's last message; the FMU's log messages on
    // the way go to the logger. Error for a failed request, LostCall when
    // the child dies, a call outlasts the time limit, or the socket holds
    // what the child did not send.
    protocol::FrameReader exchange();

    // A call that changes nothing but the FMU's state: once initialization
    // is over, sent with the next call that returns something.
    bool deferred() const { return initialized_; }

    // A set of values of one type: a request of op, deferred or answered
    template <class T>
    void setValues(protocol::Op op, const std::vector<unsigned int>& vrs,
                   const std::vector<T>& values);

    // A get of values: the reply of a request of op for vrs
    protocol::FrameReader getValues(protocol::Op op,
                                    const std::vector<unsigned int>& vrs);

    // Throws the LostCall of a child that is gone.
    void checkAlive() const;

    // Posts the queue in the page, or on the socket when it is too long
    void postQueue();

    // Waits for the child's post of the reply after the seen'th; reads the
    // socket at each slice's end. LostCall when the child is gone or
    // the time limit passed with no request of the child making progress.
    void awaitReply(std::uint32_t seen);

    // Reads the socket into the inbox, waiting for bytes when wait is set
    // (a reply sent on it), else only taking what is there. LostCall at
    // its end; afterPost: the child posted the reply, so it is alive and
    // closed its end in the calls of this exchange.
    void readSocket(bool wait, bool afterPost);

    // The next frame of the inbox; LostCall when it is not one of the
    // protocol (bytes an FMU wrote to the socket)
    bool nextFrame(protocol::FrameReader& frame, std::uint64_t& seq,
                   bool afterPost);

    // Passes the FMU's log message in frame to the logger
    void log(protocol::FrameReader& frame);

    // The reply of the exchange's last request (seq), after its ok flag
    // and the FMU's last message; Error for a failed request
    protocol::FrameReader reply(protocol::FrameReader& frame,
                                std::uint64_t seq);

    // How a call was lost
    enum class Fault {
        timedOut, // killed after the time limit
        ended, // the socket's end: the child died, or closed it
        closedChannel, // the child is alive and closed its end
        garbled // the socket carried what is not a frame: detail says what
    };

    // Ends the child (killed unless it died) and throws LostCall naming
    // the request in progress, or, afterPost, the exchange's last request.
    [[noreturn]] void lose(Fault fault, bool afterPost = false,
                           const std::string& detail = std::string());

    // Waits for the child's end; kills it if it does not end within
    // graceSeconds of closing its socket. Returns its wait status and
    // whether it ended by itself.
    int reap(double graceSeconds, bool* endedItself = nullptr);

    Logger logger_;
    std::string site_; // " in FMU 'x.fmu', instance 'x'"
    double timeout_;
    pid_t pid_ = -1;
    int socket_ = -1;
    protocol::CallPage* page_ = nullptr;
    std::vector<char> queue_;
    std::vector<Sent> sent_;
    std::uint64_t seq_ = 0;
    protocol::Inbox inbox_;
    std::string lastMessage_;
    bool initialized_ = false;
    std::uint64_t nextState_ = 0;
    std::shared_ptr<LostCall> lost_;

    // The Reals read right after the last step, read by the child after
    // the next step too, and what it read (Protocol.hpp)
    std::vector<unsigned int> readAfterStep_;
    bool stepDone_ = false; // the last request was a completed step
    bool haveRead_ = false; // readValues_ and readMessage_ hold that read
    std::vector<double> readValues_;
    std::string readMessage_;
};

} // namespace fmuImport

#endif

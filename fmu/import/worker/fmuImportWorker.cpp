// fmuImportWorker: runs one instance of an FMU for another process
// (fmuImport's Isolation::process; ChildInstance.hpp starts it).
//
//   fmuImportWorker <parent pid>
//
// with the request socket as file descriptor 3 and the page that marks the
// request in progress as 4 (Protocol.hpp). It loads the binary from the
// directory the parent unpacked the FMU in, runs each request with
// fmuImport's in-process Instance, whose errors read as they would in the
// parent, and sends the FMU's log messages as they come. It ends when the
// parent closes the socket, frees the instance, or dies (PR_SET_PDEATHSIG).
// Terminal signals (SIGINT, SIGTERM, SIGHUP, SIGQUIT) are the parent's to
// act on: ignored here. Not a program to run by hand.
#include "FmuImpl.hpp"
#include "Protocol.hpp"

#include "fmuImport/fmuImport.hpp"

#include <dirent.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

namespace {

using namespace fmuImport;
using protocol::FrameReader;
using protocol::FrameWriter;
using protocol::Kind;
using protocol::Op;

// Writes all of buffer to the socket; ends the process if the parent is
// gone (its socket closed).
void sendAll(const std::vector<char>& buffer)
{
    std::size_t done = 0;
    while (done < buffer.size()) {
        const ssize_t n = ::send(protocol::socketFd, buffer.data() + done,
                                 buffer.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            ::_exit(0);
        done += static_cast<std::size_t>(n);
    }
}

// Closes every file descriptor above the page's that the parent left open
// without close-on-exec: the child holds nothing of the parent's.
void closeInherited()
{
    std::vector<int> open;
    if (DIR* d = opendir("/proc/self/fd")) {
        while (const dirent* e = readdir(d)) {
            const int fd = std::atoi(e->d_name);
            if (fd > protocol::pageFd && fd != dirfd(d))
                open.push_back(fd);
        }
        closedir(d);
    }
    for (const int fd : open)
        ::close(fd);
}

class Worker {
public:
    explicit Worker(protocol::CallPage& page) : page_(page) { }

    // Serves requests until the end; the exit status.
    int run()
    {
        for (;;) {
            FrameReader frame(nullptr, nullptr);
            while (!inbox_.next(frame)) {
                if (inbox_.fill(protocol::socketFd) <= 0)
                    return 0; // the parent closed the socket, or died
            }
            const Op op = frame.get<Op>();
            const bool reply = frame.get<std::uint8_t>() != 0;
            const std::uint64_t seq = frame.get<std::uint64_t>();
            if (!failed_.empty()) {
                // After a failed request without reply, nothing runs until
                // the parent hears of it
                if (reply) {
                    sendError(failed_);
                    failed_.clear();
                }
                continue;
            }
            out_.clear();
            FrameWriter w(out_);
            w.put(Kind::reply).put(std::uint8_t(1));
            std::string error;
            page_.started.store(seq);
            try {
                run(op, frame, w);
            } catch (const std::exception& e) {
                error = e.what();
            }
            page_.finished.store(seq);
            if (!error.empty()) {
                if (reply)
                    sendError(error);
                else
                    failed_ = error;
            } else if (reply) {
                w.finish();
                sendAll(out_);
            }
            if (op == Op::freeInstance)
                return 0;
        }
    }

private:
    // The results go after the FMU's last message: run writes the
    // message first.
    void run(Op op, FrameReader& in, FrameWriter& out)
    {
        if (op == Op::load) {
            const std::string directory = in.getString();
            const std::string fmuPath = in.getString();
            fmu_.emplace(Fmu::Impl::openUnpacked(directory, fmuPath));
            out.put(std::string());
            return;
        }
        if (op == Op::instantiate) {
            const std::string name = in.getString();
            const bool loggingOn = in.get<std::uint8_t>() != 0;
            instance_ = std::make_unique<Instance>(
                *fmu_, name,
                [this](const std::string& instance, int status,
                       const std::string& category,
                       const std::string& message) {
                    log(instance, status, category, message);
                },
                loggingOn);
            out.put(std::string());
            return;
        }
        Instance& i = *instance_;
        // A get's reply: the instance's last message, then the values
        const auto reply
            = [&](const auto& values) { out.put(i.lastMessage()).put(values); };
        switch (op) {
        case Op::setupExperiment: {
            const double start = in.get<double>();
            const bool stopDefined = in.get<std::uint8_t>() != 0;
            i.setupExperiment(start, stopDefined, in.get<double>());
            break;
        }
        case Op::enterInitializationMode:
            i.enterInitializationMode();
            break;
        case Op::exitInitializationMode:
            i.exitInitializationMode();
            break;
        case Op::terminate:
            i.terminate();
            break;
        case Op::reset:
            i.reset();
            break;
        case Op::setReal: {
            const auto vrs = in.getVector<unsigned int>();
            i.setReal(vrs, in.getVector<double>());
            break;
        }
        case Op::setInteger: {
            const auto vrs = in.getVector<unsigned int>();
            i.setInteger(vrs, in.getVector<int>());
            break;
        }
        case Op::setBoolean: {
            const auto vrs = in.getVector<unsigned int>();
            i.setBoolean(vrs, in.getBools());
            break;
        }
        case Op::setString: {
            const auto vrs = in.getVector<unsigned int>();
            i.setString(vrs, in.getStrings());
            break;
        }
        case Op::getReal:
            return reply(i.getReal(in.getVector<unsigned int>()));
        case Op::getInteger:
            return reply(i.getInteger(in.getVector<unsigned int>()));
        case Op::getBoolean:
            return reply(i.getBoolean(in.getVector<unsigned int>()));
        case Op::getString:
            return reply(i.getString(in.getVector<unsigned int>()));
        case Op::doStep: {
            const double t = in.get<double>(), h = in.get<double>();
            const bool noSet = in.get<std::uint8_t>() != 0;
            const bool mayDiscard = in.get<std::uint8_t>() != 0;
            const auto readAfter = in.getVector<unsigned int>();
            Instance::StepResult result = Instance::StepResult::completed;
            if (mayDiscard)
                result = i.tryDoStep(t, h, noSet);
            else
                i.doStep(t, h, noSet);
            out.put(i.lastMessage()).put(static_cast<std::uint8_t>(result));
            readAfterStep(i, result, readAfter, out);
            return;
        }
        case Op::lastSuccessfulTime: {
            const double t = i.lastSuccessfulTime();
            out.put(i.lastMessage()).put(t);
            return;
        }
        case Op::getState:
            states_[in.get<std::uint64_t>()] = i.getState();
            break;
        case Op::setState:
            i.setState(state(in.get<std::uint64_t>()));
            break;
        case Op::freeState:
            states_.erase(in.get<std::uint64_t>());
            break;
        case Op::serializeState: {
            const auto bytes = i.serializeState(state(in.get<std::uint64_t>()));
            out.put(i.lastMessage()).put(bytes);
            return;
        }
        case Op::deserializeState: {
            const std::uint64_t id = in.get<std::uint64_t>();
            states_[id] = i.deserializeState(in.getVector<char>());
            break;
        }
        case Op::freeInstance:
            states_.clear();
            instance_.reset();
            out.put(std::string());
            return;
        case Op::load:
        case Op::instantiate:
            break;
        }
        out.put(i.lastMessage());
    }

    // The read that follows a completed step (Protocol.hpp): a flag, then
    // the values and the FMU's last message
    void readAfterStep(Instance& i, Instance::StepResult result,
                       const std::vector<unsigned int>& vrs, FrameWriter& out)
    {
        std::vector<double> values;
        bool read = false;
        if (result == Instance::StepResult::completed && !vrs.empty()) {
            page_.reading.store(1);
            try {
                values = i.getReal(vrs);
                read = true;
            } catch (const std::exception&) {
                // asked again, as a call of its own
            }
            page_.reading.store(0);
        }
        out.put(std::uint8_t(read));
        if (read)
            out.put(values).put(i.lastMessage());
    }

    const Instance::State& state(std::uint64_t id) const
    {
        const auto found = states_.find(id);
        if (found == states_.end())
            throw Error("fmuImportWorker: no FMU state " + std::to_string(id));
        return found->second;
    }

    void sendError(const std::string& error)
    {
        std::vector<char> buffer;
        FrameWriter w(buffer);
        w.put(Kind::reply)
            .put(std::uint8_t(0))
            .put(error)
            .put(instance_ ? instance_->lastMessage() : std::string());
        w.finish();
        sendAll(buffer);
    }

    void log(const std::string& instance, int status,
             const std::string& category, const std::string& message)
    {
        std::vector<char> buffer;
        FrameWriter w(buffer);
        w.put(Kind::log)
            .put(std::int32_t(status))
            .put(instance)
            .put(category)
            .put(message);
        w.finish();
        sendAll(buffer);
    }

    protocol::CallPage& page_;
    protocol::Inbox inbox_;
    std::vector<char> out_;
    std::string failed_; // the error of a failed request without reply
    std::optional<Fmu> fmu_;
    std::unique_ptr<Instance> instance_;
    std::map<std::uint64_t, Instance::State> states_;
};

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "fmuImportWorker runs an FMU for fmuImport "
                     "(Isolation::process); it is not run by hand\n";
        return 2;
    }
    // Ends with the parent, even when the parent is killed (SIGKILL)
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != static_cast<pid_t>(std::atol(argv[1])))
        return 0;
    for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE})
        signal(s, SIG_IGN);
    closeInherited();

    void* page = mmap(nullptr, sizeof(protocol::CallPage),
                      PROT_READ | PROT_WRITE, MAP_SHARED, protocol::pageFd, 0);
    if (page == MAP_FAILED) {
        std::cerr << "fmuImportWorker: cannot map the call page: "
                  << std::strerror(errno) << '\n';
        return 70;
    }
    Worker worker(*static_cast<protocol::CallPage*>(page));
    return worker.run();
}

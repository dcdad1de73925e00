// The requests fmuImportWorker runs (Protocol.hpp): each one with
// fmuImport's in-process Fmu and Instance, whose errors read as they would
// in the parent, its results written after the FMU's last message.
#ifndef FMUIMPORT_WORKER_REQUESTS_HPP
#define FMUIMPORT_WORKER_REQUESTS_HPP

#include "Protocol.hpp"

#include "fmuImport/fmuImport.hpp"

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fmuImport {
namespace worker {

class Requests {
public:
    // reading: the call page's mark of a step's read of the outputs; log:
    // where the FMU's log messages go
    Requests(std::atomic<std::uint32_t>& reading, Logger log);

    // Runs the request op with its arguments from in, and writes the
    // FMU's last message, then the results, to out. Error as the call.
    void run(protocol::Op op, protocol::FrameReader& in,
             protocol::FrameWriter& out);

    // The instance's last message; "" before there is one
    std::string lastMessage() const;

private:
    // The read that follows a completed step (Protocol.hpp): a flag, then
    // the values and the FMU's last message
    void readAfterStep(Instance& i, Instance::StepResult result,
                       const std::vector<unsigned int>& vrs,
                       protocol::FrameWriter& out);

    // A state by the number the parent chose for it
    const Instance::State& state(std::uint64_t id) const;

    std::atomic<std::uint32_t>& reading_;
    Logger log_;
    std::optional<Fmu> fmu_;
    std::unique_ptr<Instance> instance_;
    std::map<std::uint64_t, Instance::State> states_;
};

} // namespace worker
} // namespace fmuImport

#endif

#include "Requests.hpp"

#include "FmuImpl.hpp"

namespace fmuImport {
namespace worker {

using protocol::FrameReader;
using protocol::FrameWriter;
using protocol::Op;

Requests::Requests(std::atomic<std::uint32_t>& reading, Logger log)
    : reading_(reading), log_(std::move(log))
{
}

std::string Requests::lastMessage() const
{
    return instance_ ? instance_->lastMessage() : std::string();
}

void Requests::run(Op op, FrameReader& in, FrameWriter& out)
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
        instance_ = std::make_unique<Instance>(*fmu_, name, log_, loggingOn);
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
        i.getState(states_[in.get<std::uint64_t>()]);
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

void Requests::readAfterStep(Instance& i, Instance::StepResult result,
                             const std::vector<unsigned int>& vrs,
                             FrameWriter& out)
{
    std::vector<double> values;
    bool read = false;
    if (result == Instance::StepResult::completed && !vrs.empty()) {
        reading_.store(1);
        try {
            values = i.getReal(vrs);
            read = true;
        } catch (const std::exception&) {
            // asked again, as a call of its own
        }
        reading_.store(0);
    }
    out.put(std::uint8_t(read));
    if (read)
        out.put(values).put(i.lastMessage());
}

const Instance::State& Requests::state(std::uint64_t id) const
{
    const auto found = states_.find(id);
    if (found == states_.end())
        throw Error("fmuImportWorker: no FMU state " + std::to_string(id));
    return found->second;
}

} // namespace worker
} // namespace fmuImport

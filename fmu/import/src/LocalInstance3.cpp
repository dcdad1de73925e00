// The FMI 3.0 calls of LocalInstance: the same instance, through the fmi3
// functions. Co-simulation without event mode: fmi3InstantiateCoSimulation
// with eventModeUsed and earlyReturnAllowed false, so that the FMU handles
// its events inside fmi3DoStep; a step that asks for event handling or
// returns early anyway is an Error naming what it asked for. The get and
// set calls are in LocalInstance3Values.cpp.
#include "LocalInstance.hpp"

#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>

namespace fmuImport {

namespace {

extern "C" void fmuImportLogger3(fmi3InstanceEnvironment environment,
                                 fmi3Status status, fmi3String category,
                                 fmi3String message)
{
    const UnmarkedCallback host;
    try {
        auto* instance = static_cast<LocalInstance*>(environment);
        instance->receive(instance->name, status, category ? category : "",
                          message ? message : "");
    } catch (...) {
        // An exception must not cross the FMU's C frames; the message is lost.
    }
}

} // namespace

ElementPlan makeElementPlan(
    const std::vector<Variable>& variables,
    const std::unordered_map<unsigned int, std::size_t>& byReference,
    const std::vector<unsigned int>& vrs, Type type, const std::string& where)
{
    ElementPlan p;
    p.key = vrs;
    p.type = type;
    // array value reference -> (group, offset of its first element)
    std::unordered_map<unsigned int, std::pair<std::size_t, std::size_t>>
        arrays;
    std::unordered_map<unsigned int, std::vector<bool>> covered;
    for (const unsigned int vr : vrs) {
        const auto found = byReference.find(vr);
        if (found == byReference.end())
            throw Error(where + ": value reference " + std::to_string(vr)
                        + " is no variable of the FMU");
        const Variable& v = variables[found->second];
        const bool fits = v.type == type
            || (type == Type::Integer && v.type == Type::Enumeration);
        if (!fits)
            throw Error(where + ": variable '" + v.name + "' is a " + v.typeName
                        + ", not of this function's type");
        const std::string typeName
            = v.typeName == "Enumeration" ? "Int64" : v.typeName;
        auto array = arrays.find(v.arrayValueReference);
        if (array == arrays.end()) {
            std::size_t g = 0;
            while (g < p.groups.size() && p.groups[g].typeName != typeName)
                ++g;
            if (g == p.groups.size())
                p.groups.push_back({typeName, {}, 0});
            std::size_t count = 1;
            for (const std::size_t n : v.dimensions)
                count *= n;
            array = arrays
                        .emplace(v.arrayValueReference,
                                 std::make_pair(g, p.groups[g].count))
                        .first;
            p.groups[g].refs.push_back(v.arrayValueReference);
            p.groups[g].count += count;
            covered[v.arrayValueReference].assign(count, false);
        }
        p.where.emplace_back(array->second.first,
                             array->second.second + v.element);
        covered[v.arrayValueReference][v.element] = true;
    }
    for (const auto& c : covered)
        for (const bool b : c.second)
            p.complete = p.complete && b;
    p.direct = p.groups.size() == 1 && p.groups[0].count == vrs.size();
    for (std::size_t k = 0; k < p.where.size() && p.direct; ++k)
        p.direct = p.where[k].first == 0 && p.where[k].second == k;
    return p;
}

const ElementPlan& LocalInstance::plan(const std::vector<unsigned int>& vrs,
                                       Type type, const char* function)
{
    if (const ElementPlan* known = plans_.find(vrs, type))
        return *known;
    return plans_.add(
        makeElementPlan(fmu->description.variables, fmu->byReference, vrs, type,
                        std::string(function) + " in FMU '" + fmuPath
                            + "', instance '" + name + "'"));
}

void LocalInstance::instantiate3(bool loggingOn)
{
    // A path with a trailing separator, not a URI (FMI 3.0, 2.3.1)
    const std::string resources = (fmu->root / "resources").string() + "/";
    component_ = call(
        "fmi3InstantiateCoSimulation", std::numeric_limits<double>::quiet_NaN(),
        api3().InstantiateCoSimulation, name.c_str(),
        fmu->description.guid.c_str(), resources.c_str(), fmi3False,
        loggingOn ? fmi3True : fmi3False, fmi3False /* eventModeUsed */,
        fmi3False /* earlyReturnAllowed */, nullptr, std::size_t(0),
        static_cast<void*>(this), fmuImportLogger3, nullptr);
    if (!component_) {
        --fmu->liveInstances;
        admitted_ = false;
        std::string message = "fmi3InstantiateCoSimulation failed in FMU '"
            + fmuPath + "', instance '" + name + "'";
        if (!lastError_.empty())
            message += ": " + lastError_;
        throw Error(message);
    }
}

void LocalInstance::enterInitializationMode3()
{
    check(call("fmi3EnterInitializationMode", time,
               api3().EnterInitializationMode, component_, fmi3False, 0.0,
               startTime_, stopTimeDefined_ ? fmi3True : fmi3False, stopTime_),
          "fmi3EnterInitializationMode");
    initializing_ = true;
}

Instance::StepResult
LocalInstance::doStep3(double currentTime, double stepSize,
                       bool noSetFMUStatePriorToCurrentPoint, bool mayDiscard)
{
    fmi3Boolean eventHandlingNeeded = fmi3False,
                terminateSimulation = fmi3False, earlyReturn = fmi3False;
    fmi3Float64 reached = currentTime;
    const fmi3Status status = call(
        "fmi3DoStep", currentTime, api3().DoStep, component_, currentTime,
        stepSize, noSetFMUStatePriorToCurrentPoint ? fmi3True : fmi3False,
        &eventHandlingNeeded, &terminateSimulation, &earlyReturn, &reached);
    lastSuccessfulTime_ = reached;
    if (status == fmi3Discard && mayDiscard)
        return terminateSimulation ? Instance::StepResult::terminated
                                   : Instance::StepResult::discarded;
    check(status, "fmi3DoStep", currentTime);
    // FMI 3.0 asks to end the simulation with fmi3OK too (Reference FMU
    // Stair): its outputs are those of lastSuccessfulTime
    if (terminateSimulation && mayDiscard)
        return Instance::StepResult::terminated;
    std::string refused;
    if (terminateSimulation)
        refused = "the FMU asks to end the simulation (terminateSimulation)";
    else if (eventHandlingNeeded)
        refused = "the FMU asks for event handling (eventHandlingNeeded), "
                  "which the importer cannot drive: it instantiates with "
                  "eventModeUsed = false, where the FMU handles its events "
                  "itself";
    else if (earlyReturn)
        refused = "the FMU returned early (earlyReturn), which the importer "
                  "did not allow";
    if (refused.empty())
        return Instance::StepResult::completed;
    std::ostringstream s;
    s.precision(17);
    s << "fmi3DoStep at t = " << currentTime << " in FMU '" << fmuPath
      << "', instance '" << name << "': " << refused
      << " (lastSuccessfulTime = " << reached << ")";
    throw Error(s.str());
}

void* LocalInstance::getState3(void* reuse)
{
    fmi3FMUState raw = reuse;
    check(call("fmi3GetFMUState", time, api3().GetFMUState, component_, &raw),
          "fmi3GetFMUState", time);
    return raw;
}

void LocalInstance::setState3(void* state)
{
    check(call("fmi3SetFMUState", time, api3().SetFMUState, component_, state),
          "fmi3SetFMUState", time);
}

void LocalInstance::freeState3(void* state) noexcept
{
    call("fmi3FreeFMUState", time, api3().FreeFMUState, component_, &state);
}

std::vector<char> LocalInstance::serializeState3(void* state)
{
    std::size_t size = 0;
    check(call("fmi3SerializedFMUStateSize", time,
               api3().SerializedFMUStateSize, component_, state, &size),
          "fmi3SerializedFMUStateSize");
    std::vector<char> bytes(size);
    check(call("fmi3SerializeFMUState", time, api3().SerializeFMUState,
               component_, state, reinterpret_cast<fmi3Byte*>(bytes.data()),
               size),
          "fmi3SerializeFMUState");
    return bytes;
}

void* LocalInstance::deserializeState3(const std::vector<char>& bytes)
{
    fmi3FMUState raw = nullptr;
    check(call("fmi3DeserializeFMUState", time, api3().DeserializeFMUState,
               component_, reinterpret_cast<const fmi3Byte*>(bytes.data()),
               bytes.size(), &raw),
          "fmi3DeserializeFMUState");
    return raw;
}

} // namespace fmuImport

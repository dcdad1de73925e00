// What the fmi3 entry points (fmi3Functions.cpp, fmi3Values.cpp,
// fmi3CoSimulation.cpp) share: an FMI 3.0 instance is the FMI 2.0 instance
// (FmuInstance: the same state machine, value array, FMU states) with the
// FMI 3.0 logger in front of it and the FMI 3.0 value references
// (Fmi3Variables: an array is one value reference) mapped to the table's.
#ifndef FMU_EXPORT_ENTRYPOINTS3_HPP
#define FMU_EXPORT_ENTRYPOINTS3_HPP

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

#include "EntryPoints.hpp"
#include "Fmi3Variables.hpp"
#include "fmi3FunctionTypes.h"

namespace fmuExport {

class Fmi3Instance {
public:
    Fmi3Instance(std::unique_ptr<Model> model, const std::string& instanceName,
                 fmi3InstanceEnvironment environment,
                 fmi3LogMessageCallback logMessage, bool loggingOn)
        : environment_(environment), logMessage_(logMessage),
          variables_(model->variables()),
          core_(std::move(model), instanceName,
                fmi2CallbackFunctions {&Fmi3Instance::forward, nullptr, nullptr,
                                       nullptr, this},
                loggingOn, "fmi3")
    {
        // Messages name the FMI 3.0 variable (an array), not its element
        core_.setVariableNames([this](fmi2ValueReference element) {
            const ArrayVariable& v = variables_.owner(element);
            return v.name + " (value reference "
                + std::to_string(v.valueReference) + ")";
        });
    }

    Fmi3Instance(const Fmi3Instance&) = delete;
    Fmi3Instance& operator=(const Fmi3Instance&) = delete;

    FmuInstance& core() { return core_; }

    //- The table's value references of the elements of `vr`, in order;
    //  UsageError for a value reference that is no FMI 3.0 variable or
    //  when the elements are not `nValues`. Kept for the lists asked for
    //  before (an importer asks for the same few lists every step): a get
    //  or set then allocates nothing and maps nothing again
    const std::vector<fmi2ValueReference>&
    elements(const fmi3ValueReference vr[], std::size_t nvr,
             std::size_t nValues) const
    {
        for (const ElementList& known : elementLists_) {
            if (known.arrays.size() == nvr
                && std::equal(known.arrays.begin(), known.arrays.end(), vr)) {
                return checkedCount(known.elements, nValues);
            }
        }
        ElementList list;
        list.arrays.assign(vr, vr + nvr);
        for (std::size_t i = 0; i < nvr; ++i) {
            const ArrayVariable* v = variables_.find(vr[i]);
            if (v == nullptr) {
                throw UsageError("value reference " + std::to_string(vr[i])
                                 + " is not a variable of the FMI 3.0 "
                                   "interface");
            }
            list.elements.insert(list.elements.end(), v->elements.begin(),
                                 v->elements.end());
        }
        if (elementLists_.size() == maxElementLists) {
            elementLists_.clear(); // lists that change every call
        }
        elementLists_.push_back(std::move(list));
        return checkedCount(elementLists_.back().elements, nValues);
    }

private:
    //- A list of arrays' value references and their elements'
    struct ElementList {
        std::vector<fmi3ValueReference> arrays;
        std::vector<fmi2ValueReference> elements;
    };

    static constexpr std::size_t maxElementLists = 16;

    //- The elements, UsageError unless they are `nValues`
    static const std::vector<fmi2ValueReference>&
    checkedCount(const std::vector<fmi2ValueReference>& elements,
                 std::size_t nValues)
    {
        if (elements.size() != nValues) {
            throw UsageError("nValues = " + std::to_string(nValues)
                             + ", the value references have "
                             + std::to_string(elements.size()) + " values");
        }
        return elements;
    }

    //- elements()'s lists
    mutable std::vector<ElementList> elementLists_;

    //- FmuInstance's fmi2 logger, passed on to the fmi3 one
    static void forward(fmi2ComponentEnvironment environment, fmi2String,
                        fmi2Status status, fmi2String category,
                        fmi2String format, ...)
    {
        const auto* self = static_cast<const Fmi3Instance*>(environment);
        if (self->logMessage_ == nullptr) {
            return;
        }
        char message[2048];
        va_list args;
        va_start(args, format);
        std::vsnprintf(message, sizeof message, format, args);
        va_end(args);
        self->logMessage_(self->environment_, fmi3Status(status), category,
                          message);
    }

    fmi3InstanceEnvironment environment_;
    fmi3LogMessageCallback logMessage_;
    Fmi3Variables variables_;
    FmuInstance core_;
};

template <class Body>
inline fmi3Status guarded3(fmi3Instance c, const char* function,
                           unsigned allowed, Body&& body)
{
    if (c == nullptr) {
        return fmi3Error;
    }
    Fmi3Instance& instance = *static_cast<Fmi3Instance*>(c);
    return fmi3Status(
        instance.core().call(function, allowed, [&] { body(instance); }));
}

//- Every function of the standard that this co-simulation FMU does not
//  provide
inline fmi3Status unsupported3(fmi3Instance c, const char* function,
                               const char* reason)
{
    return guarded3(c, function, anyLiveState | fatal,
                    [&](Fmi3Instance&) { throw UsageError(reason); });
}

} // namespace fmuExport

#endif

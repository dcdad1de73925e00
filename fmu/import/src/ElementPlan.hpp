// How the importer's value references of an FMI 3.0 FMU (one per element
// of an array, fmuImport.hpp, Variable) become fmi3Get and fmi3Set calls:
// the arrays that hold the elements asked for, each passed whole and once,
// grouped by element type (one call per type), and where each element's
// value is among that call's values. Made once for a list of value
// references and kept: an importer asks for the same lists every step.
#ifndef FMUIMPORT_ELEMENTPLAN_HPP
#define FMUIMPORT_ELEMENTPLAN_HPP

#include "fmuImport/fmuImport.hpp"

#include <cstddef>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fmuImport {

struct ElementPlan {
    std::vector<unsigned int> key; // the value references it is for
    Type type = Type::Real;

    // One fmi3Get<typeName> or fmi3Set<typeName> call
    struct Group {
        std::string typeName; // "Float64"; Enumeration's call is Int64's
        std::vector<unsigned int> refs; // the arrays' value references
        std::size_t count = 0; // values of all of them
    };
    std::vector<Group> groups;

    // For each value reference of key: its group, its position there
    std::vector<std::pair<std::size_t, std::size_t>> where;

    // Every element of every array is in key: a set needs no get first
    bool complete = true;
    // One group whose values are those of key in its order: the caller's
    // vector is the call's
    bool direct = false;
};

// The plans of an instance, found by their value references
class ElementPlans {
public:
    const ElementPlan* find(const std::vector<unsigned int>& vrs,
                            Type type) const
    {
        for (const ElementPlan& p : plans_)
            if (p.type == type && p.key == vrs)
                return &p;
        return nullptr;
    }
    const ElementPlan& add(ElementPlan plan)
    {
        if (plans_.size() == 64) // lists that change every call
            plans_.clear();
        plans_.push_back(std::move(plan));
        return plans_.back();
    }

private:
    std::vector<ElementPlan> plans_;
};

// The plan of vrs, values of type (Integer also takes Enumeration);
// byReference: value reference -> position in variables. Error
// "<where>: value reference 7 ..." naming the variable when one is not a
// variable of the FMU or not of that type.
ElementPlan makeElementPlan(
    const std::vector<Variable>& variables,
    const std::unordered_map<unsigned int, std::size_t>& byReference,
    const std::vector<unsigned int>& vrs, Type type, const std::string& where);

} // namespace fmuImport

#endif

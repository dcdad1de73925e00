// The FMI 3.0 view of a model's variable table: the same variables, with
// the scalars of one vector or matrix grouped into one array variable.
// Nothing is declared twice: the arrays are derived from the FMI 2.0 names
// (docs/connector-fmu-interface.md, "FMI 3.0"):
//   X[1], X[2], ... X[n]           -> X, Float64 array of dimension n
//   X[1,1], X[1,2], ... X[r,c]     -> X, r x c (row-major, as FMI 3.0)
// Anything else stays a scalar. A line's points stay three vectors,
// shape.x, shape.y and shape.z, beside shape.tension: FMI 3.0's structured
// names allow an array only as a leaf of the name hierarchy, so shape
// cannot be both an n x 3 array and the parent of shape.tension. An array variable's value reference is that
// of its first element, so that every FMI 3.0 value reference is also an
// FMI 2.0 one and both interfaces share one value array.
#ifndef FMU_EXPORT_FMI3VARIABLES_HPP
#define FMU_EXPORT_FMI3VARIABLES_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "VariableTable.hpp"

namespace fmuExport {

struct ArrayVariable {
    std::string name;
    //- Value reference of the first element
    fmi2ValueReference valueReference = 0;
    //- Empty for a scalar
    std::vector<std::size_t> dimensions;
    //- The table's value references of the elements, row-major
    std::vector<fmi2ValueReference> elements;
    std::string description;
    //- The first element: type, causality, variability, initial, unit
    const ScalarVariable* first = nullptr;
};

class Fmi3Variables {
public:
    explicit Fmi3Variables(const VariableTable& table);

    const std::vector<ArrayVariable>& variables() const { return variables_; }

    //- The variable of an FMI 3.0 value reference, nullptr if none
    const ArrayVariable* find(fmi2ValueReference vr) const;

    //- The variable holding the table's value reference `element`
    const ArrayVariable& owner(fmi2ValueReference element) const;

private:
    std::vector<ArrayVariable> variables_;
    //- Per table value reference: index of its variable
    std::vector<std::size_t> ownerIndex_;
};

} // namespace fmuExport

#endif

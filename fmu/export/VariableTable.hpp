// The variable table of an FMU: each variable is declared once, here, with
// everything modelDescription.xml needs. Value references are assigned in
// declaration order (0, 1, 2, ...) and are indices into the value array of
// an instance.
#ifndef FMU_EXPORT_VARIABLETABLE_HPP
#define FMU_EXPORT_VARIABLETABLE_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "fmi2TypesPlatform.h"

namespace fmuExport {

enum class Causality { parameter, input, output, local };
enum class Variability { constant, fixed, continuous };
//- FMI base type, spelt as in modelDescription.xml (and fmuImport::Type);
//  a Boolean is stored as 0.0 or 1.0 in the value array
enum class Type { Real, Boolean };
//- `none` omits the attribute (required for inputs)
enum class Initial { none, exact, calculated };
//- Scalar "x", vector "x[1..3]", matrix "x[1..3,1..3]" (row, column)
enum class Shape { scalar, vector3, matrix3 };

//- Handle on the consecutive scalar variables of one declaration
struct Block {
    fmi2ValueReference first = 0;
    std::size_t size = 0;
};

struct ScalarVariable {
    std::string name;
    fmi2ValueReference valueReference = 0;
    Type type = Type::Real;
    Causality causality = Causality::parameter;
    Variability variability = Variability::fixed;
    Initial initial = Initial::none;
    std::string unit;
    std::string description;
    //- Start value, written unless initial == calculated
    double start = 0.0;
    //- Outputs: the inputs and parameters the value depends on (sorted)
    std::vector<fmi2ValueReference> dependencies;
};

class VariableTable {
public:
    //- Parameter (variability fixed, initial exact), one start per element
    Block parameter(const std::string& name, Shape shape,
                    const std::string& unit, const std::string& description,
                    const std::vector<double>& start);

    //- Continuous input, one start per element
    Block input(const std::string& name, Shape shape, const std::string& unit,
                const std::string& description,
                const std::vector<double>& start);

    //- Continuous output (initial calculated) depending on the given
    //  input and parameter blocks
    Block output(const std::string& name, Shape shape, const std::string& unit,
                 const std::string& description,
                 const std::vector<Block>& dependsOn);

    //- Continuous local variable (initial calculated): computed by the
    //  model like an output, readable, but no output
    Block local(const std::string& name, Shape shape, const std::string& unit,
                const std::string& description);

    //- Boolean constant (causality local, variability constant)
    Block booleanConstant(const std::string& name,
                          const std::string& description, bool value);

    //- Change the start values of a declared parameter or input block,
    //  one per element
    void setStart(const Block& block, const std::vector<double>& start);

    const std::vector<ScalarVariable>& variables() const { return variables_; }

    std::size_t size() const { return variables_.size(); }

private:
    Block add(const std::string& name, Shape shape, Causality causality,
              const std::string& unit, const std::string& description,
              const std::vector<double>& start,
              const std::vector<Block>& dependsOn);

    std::vector<ScalarVariable> variables_;
};

//- Number of elements of a shape (1, 3 or 9)
std::size_t shapeSize(Shape shape);

} // namespace fmuExport

#endif

#include "VariableTable.hpp"

#include <algorithm>
#include <stdexcept>

namespace fmuExport {

std::size_t shapeSize(Shape shape)
{
    switch (shape) {
    case Shape::scalar:
        return 1;
    case Shape::vector3:
        return 3;
    case Shape::matrix3:
        return 9;
    }
    return 0;
}

namespace {

std::string elementName(const std::string& name, Shape shape, std::size_t i)
{
    switch (shape) {
    case Shape::scalar:
        return name;
    case Shape::vector3:
        return name + "[" + std::to_string(i + 1) + "]";
    case Shape::matrix3:
        return name + "[" + std::to_string(i / 3 + 1) + ","
            + std::to_string(i % 3 + 1) + "]";
    }
    return name;
}

std::string elementDescription(const std::string& description, Shape shape,
                               std::size_t i)
{
    switch (shape) {
    case Shape::scalar:
        return description;
    case Shape::vector3:
        return description + ", component " + std::to_string(i + 1);
    case Shape::matrix3:
        return description + ", row " + std::to_string(i / 3 + 1) + ", column "
            + std::to_string(i % 3 + 1);
    }
    return description;
}

} // namespace

Block VariableTable::parameter(const std::string& name, Shape shape,
                               const std::string& unit,
                               const std::string& description,
                               const std::vector<double>& start)
{
    return add(name, shape, Causality::parameter, unit, description, start, {});
}

Block VariableTable::input(const std::string& name, Shape shape,
                           const std::string& unit,
                           const std::string& description,
                           const std::vector<double>& start)
{
    return add(name, shape, Causality::input, unit, description, start, {});
}

Block VariableTable::output(const std::string& name, Shape shape,
                            const std::string& unit,
                            const std::string& description,
                            const std::vector<Block>& dependsOn)
{
    return add(name, shape, Causality::output, unit, description, {},
               dependsOn);
}

Block VariableTable::local(const std::string& name, Shape shape,
                           const std::string& unit,
                           const std::string& description)
{
    return add(name, shape, Causality::local, unit, description, {}, {});
}

Block VariableTable::booleanConstant(const std::string& name,
                                     const std::string& description, bool value)
{
    ScalarVariable v;
    v.name = name;
    v.valueReference = fmi2ValueReference(variables_.size());
    v.type = Type::Boolean;
    v.causality = Causality::local;
    v.variability = Variability::constant;
    v.initial = Initial::exact;
    v.description = description;
    v.start = value ? 1.0 : 0.0;
    variables_.push_back(v);
    return Block {v.valueReference, 1};
}

void VariableTable::setStart(const Block& block,
                             const std::vector<double>& start)
{
    if (start.size() != block.size
        || block.first + block.size > variables_.size()) {
        throw std::logic_error("setStart: " + std::to_string(start.size())
                               + " start values for a block of "
                               + std::to_string(block.size));
    }
    for (std::size_t i = 0; i < block.size; ++i) {
        ScalarVariable& v = variables_[block.first + i];
        if (v.causality != Causality::parameter
            && v.causality != Causality::input) {
            throw std::logic_error("setStart: " + v.name
                                   + " is no parameter or input");
        }
        v.start = start[i];
    }
}

Block VariableTable::add(const std::string& name, Shape shape,
                         Causality causality, const std::string& unit,
                         const std::string& description,
                         const std::vector<double>& start,
                         const std::vector<Block>& dependsOn)
{
    const std::size_t n = shapeSize(shape);
    const bool calculated
        = causality == Causality::output || causality == Causality::local;
    if (!calculated && start.size() != n) {
        throw std::logic_error("variable " + name + ": " + std::to_string(n)
                               + " start values expected, got "
                               + std::to_string(start.size()));
    }
    std::vector<fmi2ValueReference> dependencies;
    for (const Block& block : dependsOn) {
        for (std::size_t i = 0; i < block.size; ++i) {
            const fmi2ValueReference vr = block.first + fmi2ValueReference(i);
            if (vr >= variables_.size()
                || (variables_[vr].causality != Causality::input
                    && variables_[vr].causality != Causality::parameter)) {
                throw std::logic_error(
                    "output " + name
                    + " depends on a value reference that "
                      "is not a declared input or parameter");
            }
            dependencies.push_back(vr);
        }
    }
    std::sort(dependencies.begin(), dependencies.end());
    dependencies.erase(std::unique(dependencies.begin(), dependencies.end()),
                       dependencies.end());

    const Block block {fmi2ValueReference(variables_.size()), n};
    for (std::size_t i = 0; i < n; ++i) {
        ScalarVariable v;
        v.name = elementName(name, shape, i);
        v.valueReference = block.first + fmi2ValueReference(i);
        v.causality = causality;
        v.variability = causality == Causality::parameter
            ? Variability::fixed
            : Variability::continuous;
        v.initial = causality == Causality::parameter ? Initial::exact
            : calculated                              ? Initial::calculated
                                                      : Initial::none;
        v.unit = unit;
        v.description = elementDescription(description, shape, i);
        v.start = calculated ? 0.0 : start[i];
        v.dependencies = dependencies;
        variables_.push_back(v);
    }
    return block;
}

} // namespace fmuExport

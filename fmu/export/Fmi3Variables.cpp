#include "Fmi3Variables.hpp"

#include <cstdlib>
#include <limits>

namespace fmuExport {

namespace {

//- "X[1,2]" -> base "X", indices {1, 2}; false for a name without indices
bool splitName(const std::string& name, std::string& base,
               std::vector<std::size_t>& indices)
{
    const std::size_t open = name.rfind('[');
    if (open == std::string::npos || open == 0 || name.back() != ']') {
        return false;
    }
    indices.clear();
    std::size_t begin = open + 1;
    while (begin < name.size() - 1) {
        const std::size_t end = name.find_first_of(",]", begin);
        const std::string number = name.substr(begin, end - begin);
        if (number.empty()
            || number.find_first_not_of("0123456789") != std::string::npos) {
            return false;
        }
        indices.push_back(std::strtoul(number.c_str(), nullptr, 10));
        begin = end + 1;
    }
    base = name.substr(0, open);
    return !indices.empty() && indices.size() <= 2;
}

bool sameKind(const ScalarVariable& a, const ScalarVariable& b)
{
    return a.type == b.type && a.causality == b.causality
        && a.variability == b.variability && a.initial == b.initial
        && a.unit == b.unit;
}

//- Indices of a complete vector (1..n) or row-major matrix (1..r, 1..c)
bool complete(const std::vector<std::vector<std::size_t>>& indices,
              std::vector<std::size_t>& dimensions)
{
    const std::size_t n = indices.size();
    const std::size_t columns = indices[0].size() == 1 ? 1 : indices.back()[1];
    if (columns == 0 || n % columns != 0) {
        return false;
    }
    for (std::size_t k = 0; k < n; ++k) {
        const bool ok = indices[k].size() == 1
            ? indices[k][0] == k + 1
            : indices[k][0] == k / columns + 1
                && indices[k][1] == k % columns + 1;
        if (!ok) {
            return false;
        }
    }
    dimensions = indices[0].size() == 1
        ? std::vector<std::size_t> {n}
        : std::vector<std::size_t> {n / columns, columns};
    return true;
}

std::string withoutSuffix(const std::string& text, const std::string& suffix)
{
    if (text.size() > suffix.size()
        && text.compare(text.size() - suffix.size(), suffix.size(), suffix)
            == 0) {
        return text.substr(0, text.size() - suffix.size());
    }
    return std::string();
}

//- The declaration's description (VariableTable adds ", component 1" or
//  ", row 1, column 1" to an element's), else a description naming the
//  FMI 2.0 elements
std::string arrayDescription(const std::string& base, std::size_t n,
                             const std::string& firstDescription)
{
    for (const char* suffix : {", component 1", ", row 1, column 1"}) {
        const std::string text = withoutSuffix(firstDescription, suffix);
        if (!text.empty()) {
            return text;
        }
    }
    return "FMI 2.0's " + base + "[1.." + std::to_string(n)
        + "]; element 1: " + firstDescription;
}

} // namespace

Fmi3Variables::Fmi3Variables(const VariableTable& table)
{
    const std::vector<ScalarVariable>& scalars = table.variables();
    std::size_t k = 0;
    while (k < scalars.size()) {
        const ScalarVariable& v = scalars[k];
        ArrayVariable array;
        array.name = v.name;
        array.valueReference = v.valueReference;
        array.elements = {v.valueReference};
        array.description = v.description;
        array.first = &v;
        std::string base;
        std::vector<std::size_t> index;
        if (splitName(v.name, base, index)) {
            std::vector<std::vector<std::size_t>> indices {index};
            std::size_t end = k + 1;
            std::string nextBase;
            while (end < scalars.size()
                   && splitName(scalars[end].name, nextBase, index)
                   && nextBase == base && index.size() == indices[0].size()
                   && sameKind(scalars[end], v)) {
                indices.push_back(index);
                ++end;
            }
            std::vector<std::size_t> dimensions;
            if (complete(indices, dimensions)) {
                array.name = base;
                array.dimensions = dimensions;
                array.elements.clear();
                for (std::size_t i = k; i < end; ++i) {
                    array.elements.push_back(scalars[i].valueReference);
                }
                array.description
                    = arrayDescription(base, end - k, v.description);
                k = end;
            } else {
                ++k;
            }
        } else {
            ++k;
        }
        variables_.push_back(std::move(array));
    }
    ownerIndex_.assign(scalars.size(), std::numeric_limits<std::size_t>::max());
    for (std::size_t i = 0; i < variables_.size(); ++i) {
        for (fmi2ValueReference e : variables_[i].elements) {
            ownerIndex_[e] = i;
        }
    }
}

const ArrayVariable* Fmi3Variables::find(fmi2ValueReference vr) const
{
    if (vr >= ownerIndex_.size()) {
        return nullptr;
    }
    const ArrayVariable& v = variables_[ownerIndex_[vr]];
    return v.valueReference == vr ? &v : nullptr;
}

const ArrayVariable& Fmi3Variables::owner(fmi2ValueReference element) const
{
    return variables_.at(ownerIndex_.at(element));
}

} // namespace fmuExport

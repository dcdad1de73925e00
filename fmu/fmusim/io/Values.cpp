#include "io/Values.hpp"

#include "Session.hpp"
#include "io/Csv.hpp"

#include <cmath>

namespace fmusim {

std::vector<const fmuImport::Variable*> outputsOf(const fmuImport::Fmu& fmu)
{
    std::vector<const fmuImport::Variable*> outputs;
    for (const fmuImport::Variable& v : fmu.modelDescription().variables)
        if (v.causality == fmuImport::Causality::output)
            outputs.push_back(&v);
    return outputs;
}

std::vector<std::string>
readValues(fmuImport::Instance& instance,
           const std::vector<const fmuImport::Variable*>& variables)
{
    using fmuImport::Type;
    // One fmi2Get call per type: gather the value references, then scatter.
    std::vector<unsigned int> vrs[4];
    std::vector<std::size_t> where[4];
    auto group = [](Type t) {
        return t == Type::Real   ? 0
            : t == Type::Boolean ? 2
            : t == Type::String  ? 3
                                 : 1;
    };
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const int g = group(variables[i]->type);
        vrs[g].push_back(variables[i]->valueReference);
        where[g].push_back(i);
    }
    std::vector<std::string> text(variables.size());
    if (!vrs[0].empty()) {
        const std::vector<double> values = instance.getReal(vrs[0]);
        for (std::size_t k = 0; k < values.size(); ++k) {
            const fmuImport::Variable& v = *variables[where[0][k]];
            if (!std::isfinite(values[k]))
                throw fmuImport::Error(nonFiniteMessage(
                    instance,
                    (v.causality == fmuImport::Causality::output ? "output '"
                                                                 : "variable '")
                        + v.name + "'",
                    values[k], instance.time()));
            text[where[0][k]] = formatNumber(values[k]);
        }
    }
    if (!vrs[1].empty()) {
        const std::vector<int> values = instance.getInteger(vrs[1]);
        for (std::size_t k = 0; k < values.size(); ++k)
            text[where[1][k]] = std::to_string(values[k]);
    }
    if (!vrs[2].empty()) {
        const std::vector<bool> values = instance.getBoolean(vrs[2]);
        for (std::size_t k = 0; k < values.size(); ++k)
            text[where[2][k]] = values[k] ? "1" : "0";
    }
    if (!vrs[3].empty()) {
        const std::vector<std::string> values = instance.getString(vrs[3]);
        for (std::size_t k = 0; k < values.size(); ++k)
            text[where[3][k]] = csvField(values[k]);
    }
    return text;
}

std::string nonFiniteMessage(const fmuImport::Instance& instance,
                             const std::string& what, double value, double time)
{
    return instanceName(instance) + ": " + what + " is " + formatNumber(value)
        + " at t = " + formatNumber(time) + ", expected a finite number";
}

} // namespace fmusim

// What a model gives the FMI layer: its identity, its variable table and two
// computations on the value array (indexed by value reference).
#ifndef FMU_EXPORT_MODEL_HPP
#define FMU_EXPORT_MODEL_HPP

#include <memory>
#include <string>

#include "VariableTable.hpp"

namespace fmuExport {

struct ModelIdentity {
    //- modelIdentifier and modelName, also the name of the binary
    std::string modelIdentifier;
    //- One-line description
    std::string description;
    //- Version of the model, part of the GUID
    std::string version;
    //- HTML fragment stating the law, for documentation/index.html
    std::string lawHtml;
};

class Model {
public:
    virtual ~Model() = default;

    const ModelIdentity& identity() const { return identity_; }

    const VariableTable& variables() const { return variables_; }

    //- Throws an exception naming the parameter and the allowed range for
    //  a parameter value the model cannot use
    virtual void checkParameters(const double* values) const = 0;

    //- Computes every output from the parameters and inputs in `values`;
    //  throws (naming the variable) where the outputs are undefined. On
    //  failure the outputs in `values` are left unchanged.
    virtual void computeOutputs(double* values) const = 0;

protected:
    explicit Model(ModelIdentity identity)
        : identity_(std::move(identity))
    {
    }

    VariableTable& table() { return variables_; }

private:
    ModelIdentity identity_;
    VariableTable variables_;
};

//- Defined once per FMU, by the model's own source
std::unique_ptr<Model> createModel();

} // namespace fmuExport

#endif

// What a model gives the FMI layer: its identity, its variable table and two
// computations on the value array (indexed by value reference). A model
// with internal dynamics (state that is not in the value array, e.g. the
// nodes of a mooring line) also overrides the four state hooks, whose
// defaults describe a model whose state is the value array alone.
#ifndef FMU_EXPORT_MODEL_HPP
#define FMU_EXPORT_MODEL_HPP

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

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

    //- Builds what the parameters in `values` determine (the law), and so
    //  checks them, for the computations that follow; throws
    //  connectors::ParameterError (its code and the parameter's name) for a
    //  value the model cannot use. The FMI layer (FmuInstance) calls it once
    //  per parameter set: before the first computation, at the latest in
    //  fmi2ExitInitializationMode, and again only after a parameter changed
    //  (set before initialization, or restored with an FMU state).
    virtual void setParameters(const double* values) = 0;

    //- Computes every output from the inputs in `values` with the
    //  parameters of the last setParameters; throws (naming the variable)
    //  where the outputs are undefined. On failure the outputs in `values`
    //  are left unchanged.
    virtual void computeOutputs(double* values) const = 0;

    //- fmi2ExitInitializationMode, after setParameters: sets up the
    //  internal state for the parameters and inputs in `values` at `time`
    virtual void initializeState(const double* values, double time)
    {
        (void)values;
        (void)time;
    }

    //- fmi2DoStep: advances the internal state from `time` to `time + h`
    //  (the inputs in `values` are those at time + h) and computes every
    //  output; on failure it throws and changes neither state nor outputs
    virtual void doStep(double* values, double time, double h)
    {
        (void)time;
        (void)h;
        computeOutputs(values);
    }

    //- Outputs and locals, one block of consecutive value references,
    //  that doStep may leave out: the FMI layer has completeOutputs
    //  compute them once a step, when fmi2GetReal first asks for one of
    //  them (empty, the default: doStep computes every output)
    virtual Block deferredOutputs() const { return {}; }

    //- Computes the deferredOutputs() for the internal state and the
    //  inputs in `values`, after doStep or a restored FMU state, and
    //  writes nothing else; throws (and writes nothing) where they are
    //  undefined
    virtual void completeOutputs(double* values) const { (void)values; }

    //- The internal state, saved with the value array in FMU states and
    //  serialized after it; empty for a model without one
    virtual std::vector<double> internalState() const { return {}; }

    //- The same into `state`, whose storage a model may keep (fmi2GetFMUstate
    //  into a state it returned before allocates nothing then)
    virtual void saveInternalState(std::vector<double>& state) const
    {
        state = internalState();
    }

    //- Restores a state returned by internalState() for the parameters in
    //  `values` (empty: back to before initializeState; not empty: after
    //  setParameters for them); throws
    //  std::invalid_argument for data that do not fit
    virtual void setInternalState(const double* values,
                                  const std::vector<double>& state)
    {
        (void)values;
        if (!state.empty()) {
            throw std::invalid_argument(identity_.modelIdentifier
                                        + " has no internal state, the "
                                          "saved state has "
                                        + std::to_string(state.size())
                                        + " values");
        }
    }

protected:
    explicit Model(ModelIdentity identity) : identity_(std::move(identity)) { }

    VariableTable& table() { return variables_; }

private:
    ModelIdentity identity_;
    VariableTable variables_;
};

//- Defined once per FMU, by the model's own source
std::unique_ptr<Model> createModel();

} // namespace fmuExport

#endif

// ConnectorFmuModel: the one base of every connector FMU's model. It declares
// the variables of the connector FMU interface (docs/connector-fmu-interface.md)
// and maps the value array to the law's kinematics and back; a connector
// model adds only its law's mapping:
//   - its parameters, declared with table().parameter() in its constructor,
//     before or after declareBodies() (the order is that of the value
//     references, so that of modelDescription.xml);
//   - setParameters(): its parameters to its law, kept in a BuiltLaw (the
//     FMI layer calls it once per parameter set; LawFmuModel does this for a
//     law built from one parameter struct, each parameter bound to its
//     field);
//   - evaluate(): the law's result to the outputs;
//   - optionally outputs of its own after the 17 interface outputs
//     (extraOutput(), filled in by evaluate() in declaration order), and
//     after them local variables (extraLocal(), likewise);
//   - optionally an internal state through Model's state hooks
//     (initializeState, doStep, internalState, setInternalState), with
//     writeOutputs() to publish what a step computed.
#ifndef FMU_EXPORT_CONNECTORFMUMODEL_HPP
#define FMU_EXPORT_CONNECTORFMUMODEL_HPP

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "BodyInputs.hpp"
#include "Model.hpp"
#include "common/Kinematics.hpp"

namespace fmuExport {

//- How a connector words the interface variables in modelDescription.xml
struct ConnectorWording {
    //- The connector in "force of the <noun> on A"
    std::string noun = "connector";
    //- What A.p and B.p are, e.g. "attachment point on A"
    std::string A_p = "attachment point on A";
    std::string B_p = "attachment point on B";
    //- Descriptions of the five diagnostics
    std::string length = "distance between the attachment points";
    std::string lengthRate = "time derivative of the length";
    std::string tension = "axial force, positive when the connector pulls the "
                          "bodies together";
    std::string potentialEnergy = "energy stored in the connector";
    std::string dissipatedPower = "power dissipated by the connector (removed "
                                  "from the bodies and not stored), never "
                                  "negative";
};

//- What one evaluation gives the outputs: the law's loads and diagnostics,
//  then the values of the model's extra outputs in declaration order, then
//  those of its local variables
struct ConnectorOutputs {
    //- Implicit: a model without extra outputs returns its law's result
    ConnectorOutputs(const connectors::ConnectorResult& result,
                     std::vector<double> extraValues = {},
                     std::vector<double> localValues = {})
        : loads(result), extra(std::move(extraValues)),
          locals(std::move(localValues))
    {
    }

    connectors::ConnectorResult loads;
    std::vector<double> extra, locals;
};

//- A connector model's law, built by its setParameters for one parameter
//  set (and so checked once) and used by every evaluation until the next
template <class Law> class BuiltLaw {
public:
    //- Builds the law from `parameters`; if that throws, no law is kept
    template <class Parameters> void build(const Parameters& parameters)
    {
        law_.reset();
        law_.emplace(parameters);
    }

    Law& get() { return law_ ? *law_ : missing(); }
    const Law& get() const { return law_ ? *law_ : missing(); }

private:
    [[noreturn]] static Law& missing()
    {
        throw std::logic_error("a connector law is used before "
                               "setParameters built it");
    }

    std::optional<Law> law_;
};

class ConnectorFmuModel : public Model {
public:
    //- Evaluates the law for the parameters and inputs in `values` and
    //  writes every output (see writeOutputs)
    void computeOutputs(double* values) const final;

protected:
    //- For each interface output, the input and parameter blocks it
    //  depends on
    struct OutputDependencies {
        std::vector<Block> loads, length, lengthRate, tension, potentialEnergy,
            dissipatedPower;
    };

    //- Declares the parameters A.p and B.p
    ConnectorFmuModel(ModelIdentity identity, ConnectorWording wording = {});

    //- Declares the inputs of A and of B, both starting at the origin with
    //  identity orientation and at rest (B as the bridge feeds the fixed
    //  world to a connector without a body B), and sets the start value of
    //  B.p to `B_p0`: the attachment on B, the anchor in the world, where
    //  the start values are a configuration without load
    void declareBodies(const std::vector<double>& B_p0);

    //- Declares the Boolean constant inputsStartAtRest = true: the start
    //  values of the inputs and parameters are a configuration without load
    //  (docs/connector-fmu-interface.md, "Rest configuration")
    void declareStartAtRest();

    //- Declares A.F, A.M, B.F, B.M and the five diagnostics (after
    //  declareBodies)
    void declareOutputs(const OutputDependencies& dependencies);

    //- Declares an output of the model's own, right after the interface
    //  outputs and the extra outputs declared before it
    Block extraOutput(const std::string& name, Shape shape,
                      const std::string& unit, const std::string& description,
                      const std::vector<Block>& dependsOn);

    //- Declares a variable of the model's own that evaluate() computes
    //  with the outputs but that is no output (causality local: read with
    //  fmi2GetReal when asked for, not among the outputs importers record
    //  by default), after the extra outputs and the locals declared before
    Block extraLocal(const std::string& name, Shape shape,
                     const std::string& unit, const std::string& description);

    //- The connector law built by setParameters, with the previous outputs
    //  in `values`: the outputs for the kinematics of A and B
    virtual ConnectorOutputs
    evaluate(const double* values, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const = 0;

    //- Writes every output and local; throws std::range_error naming the
    //  first non-finite one, and writes nothing then
    void writeOutputs(double* values, const ConnectorOutputs& outputs) const;
    //- Writes the interface outputs of `loads` and the first `n` extra
    //  outputs (`extra`), checked as writeOutputs: what a step computes
    //  when the rest are deferred (Model::deferredOutputs)
    void writeLeadingOutputs(double* values,
                             const connectors::ConnectorResult& loads,
                             const double* extra, std::size_t n) const;
    //- Writes the extra outputs of `outputs` after the first `n` and the
    //  locals, checked as writeOutputs (Model::completeOutputs)
    void writeTrailingOutputs(double* values, const ConnectorOutputs& outputs,
                              std::size_t n) const;
    //- The block of those: the extra outputs after the first `n` and the
    //  locals (declared after every extra output)
    Block trailingOutputs(std::size_t n) const;

    //- Blocks that the geometry depends on: A.p, B.p, A.r, A.R, B.r, B.R
    std::vector<Block> positionBlocks() const;
    //- Blocks that velocities depend on: A.v, A.omega, B.v, B.omega
    std::vector<Block> velocityBlocks() const;

    //- Dependencies of a connector between P and Q whose loads depend on
    //  the positions, the velocities and the blocks `law`: length on the
    //  positions, lengthRate on positions and velocities, tension and
    //  dissipatedPower on what the loads depend on, potentialEnergy on
    //  nothing (a model that stores energy sets it after)
    OutputDependencies
    pointToPointDependencies(const std::vector<Block>& law) const;

    //- A parameter that is 0 or 1; throws connectors::ParameterError
    //  (outOfRange) naming it otherwise
    bool flag(const double* values, Block block) const;

    static double scalar(const double* values, Block block);
    static connectors::Vector3 vector3(const double* values, Block block);
    static std::vector<Block> join(std::vector<Block> a,
                                   const std::vector<Block>& b);

    Block A_p, B_p;
    BodyInputs A, B;

private:
    static void interfaceValues(const connectors::ConnectorResult& r,
                                double* v);
    //- Throws std::range_error naming the first of the `n` values `v`
    //  (value references from `first`) that is not finite
    void check(const double* v, fmi2ValueReference first, std::size_t n,
               const char* kind = "output") const;
    void checkTrailing(const ConnectorOutputs& outputs, std::size_t n) const;

    ConnectorWording wording_;
    bool bodiesDeclared_ = false, outputsDeclared_ = false;
    //- First value reference of the interface outputs; number of scalar
    //  extra outputs after them
    fmi2ValueReference firstOutput_ = 0;
    std::size_t extraCount_ = 0;
    //- First value reference and number of the scalar locals
    fmi2ValueReference firstLocal_ = 0;
    std::size_t localCount_ = 0;
};

} // namespace fmuExport

#endif

// Base of every two-body connector FMU: declares the variables of the
// connector FMU interface (docs/connector-fmu-interface.md) and maps the
// value array to and from the connector law's structs. A connector model
// declares its own parameters, then its outputs, and evaluates its law.
#ifndef FMU_EXPORT_CONNECTORMODEL_HPP
#define FMU_EXPORT_CONNECTORMODEL_HPP

#include <vector>

#include "BodyInputs.hpp"
#include "Model.hpp"
#include "common/Kinematics.hpp"

namespace fmuExport {

class ConnectorModel : public Model {
public:
    using BodyInputs = fmuExport::BodyInputs;

    void computeOutputs(double* values) const final;

protected:
    //- For each output group, the input and parameter blocks it depends on
    struct OutputDependencies {
        std::vector<Block> loads, length, lengthRate, tension, potentialEnergy,
            dissipatedPower;
    };

    //- Declares the parameters A.p, B.p and the inputs of A and B, with B
    //  one metre from A along x (B.r start) so that start values give a
    //  defined geometry
    explicit ConnectorModel(ModelIdentity identity);

    //- Declares the Boolean constant inputsStartAtRest = true: the start
    //  values of the inputs and parameters are a configuration without load
    //  (docs/connector-fmu-interface.md, "Rest configuration")
    void declareStartAtRest();

    //- Declares A.F, A.M, B.F, B.M and the five diagnostics
    void declareOutputs(const OutputDependencies& dependencies);

    //- Blocks that the geometry depends on: A.p, B.p, A.r, A.R, B.r, B.R
    std::vector<Block> positionBlocks() const;
    //- Blocks that velocities depend on: A.v, A.omega, B.v, B.omega
    std::vector<Block> velocityBlocks() const;

    //- The connector law for the parameters in `values`
    virtual connectors::ConnectorResult
    evaluate(const double* values, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const = 0;

    static double scalar(const double* values, Block block);
    static connectors::Vector3 vector3(const double* values, Block block);
    static std::vector<Block> join(std::vector<Block> a,
                                   const std::vector<Block>& b);

    Block A_p, B_p;
    BodyInputs A, B;

private:
    //- First value reference of the 17 outputs, in declaration order
    fmi2ValueReference firstOutput_ = 0;
};

} // namespace fmuExport

#endif

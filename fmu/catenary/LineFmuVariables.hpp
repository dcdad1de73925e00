// Variables shared by the mooring line FMUs (catenary.fmu, mooringLine.fmu):
// the connector interface (attachment points, kinematics of A and B, loads
// and diagnostics) and the line's own outputs (end tensions, grounded
// length, H, V and a fixed number of points along the line).
#ifndef FMU_CATENARY_LINEFMUVARIABLES_HPP
#define FMU_CATENARY_LINEFMUVARIABLES_HPP

#include <string>
#include <vector>

#include "BodyInputs.hpp"
#include "VariableTable.hpp"
#include "common/Kinematics.hpp"

namespace lineFmu {

using fmuExport::Block;

//- Points along the line in the shape outputs (fixed at build time)
inline constexpr int shapePoints = 11;

using fmuExport::BodyInputs;

struct LineVariables {
    Block A_p, B_p;
    BodyInputs A, B;
    //- First output (A.F[1]); every output follows in declaration order
    Block firstOutput;
    Block H, V;
};

//- Output values in declaration order of declareOutputs
struct LineOutputs {
    connectors::ConnectorResult loads;
    double fairleadTension = 0.0, anchorTension = 0.0, groundedLength = 0.0;
    double H = 0.0, V = 0.0;
    //- shapePoints points from the fairlead P to Q, global frame [m]
    std::vector<connectors::Vector3> shape;
};

//- Dependencies of each output group
struct LineDependencies {
    std::vector<Block> loads, length, lengthRate, energy, dissipation;
};

//- A.p and B.p (B.p: an anchor, global, when B is the world)
void declareAttachments(fmuExport::VariableTable& table, LineVariables& v);

//- Inputs of A and B; B starts at `B_r0`
void declareBodies(fmuExport::VariableTable& table, LineVariables& v,
                   const std::vector<double>& B_r0);

//- The 17 interface outputs, then fairleadTension, anchorTension,
//  groundedLength, H, V, shape.x[1..N], shape.y[1..N], shape.z[1..N]
void declareOutputs(fmuExport::VariableTable& table, LineVariables& v,
                    const LineDependencies& d);

std::vector<Block> positionBlocks(const LineVariables& v);
std::vector<Block> velocityBlocks(const LineVariables& v);
std::vector<Block> join(std::vector<Block> a, const std::vector<Block>& b);

inline connectors::Vector3 vector3(const double* values, Block block)
{
    return fmuExport::blockVector3(values, block);
}
inline connectors::BodyKinematics kinematics(const double* values,
                                             const BodyInputs& body)
{
    return fmuExport::bodyKinematics(values, body);
}

//- Writes every output; throws std::range_error naming the first
//  non-finite one (and writes nothing then)
void writeOutputs(double* values, const LineVariables& v,
                  const fmuExport::VariableTable& table,
                  const std::string& model, const LineOutputs& out);

} // namespace lineFmu

#endif

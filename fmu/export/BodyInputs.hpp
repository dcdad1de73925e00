// The inputs of one body in the connector FMU interface
// (docs/connector-fmu-interface.md): declaration in a variable table and
// mapping of the value array to the law library's kinematics. Shared by every
// connector model, whatever base it derives from.
#ifndef FMU_EXPORT_BODYINPUTS_HPP
#define FMU_EXPORT_BODYINPUTS_HPP

#include <string>
#include <vector>

#include "VariableTable.hpp"
#include "common/Kinematics.hpp"

namespace fmuExport {

//- Value references of one body's inputs
struct BodyInputs {
    Block r, R, v, omega;
};

//- Declares <body>.r (start r0), <body>.R (identity), <body>.v and
//  <body>.omega (zero)
BodyInputs declareBodyInputs(VariableTable& table, const std::string& body,
                             const std::vector<double>& r0);

//- The three values of a vector block
connectors::Vector3 blockVector3(const double* values, Block block);

//- The nine values of a 3x3 block, row by row
connectors::Matrix3 blockMatrix3(const double* values, Block block);

//- The same into m: LawFmuModel fills a law's 3x3 parameters through it,
//  out of line, where GCC cannot mistake a member of a law without one
//  for an out-of-bounds write (-Warray-bounds)
void readBlockMatrix3(const double* values, Block block,
                      connectors::Matrix3& m);

//- The body's kinematics from the value array
connectors::BodyKinematics bodyKinematics(const double* values,
                                          const BodyInputs& body);

} // namespace fmuExport

#endif

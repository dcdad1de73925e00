#include "BodyInputs.hpp"

namespace fmuExport {

BodyInputs declareBodyInputs(VariableTable& table, const std::string& body,
                             const std::vector<double>& r0)
{
    BodyInputs in;
    in.r = table.input(
        body + ".r", Shape::vector3, "m",
        "position of " + body + "'s reference point, global frame", r0);
    in.R
        = table.input(body + ".R", Shape::matrix3, "1",
                      "orientation of " + body + ", body frame to global frame",
                      {1, 0, 0, 0, 1, 0, 0, 0, 1});
    in.v = table.input(
        body + ".v", Shape::vector3, "m/s",
        "velocity of " + body + "'s reference point, global frame", {0, 0, 0});
    in.omega = table.input(body + ".omega", Shape::vector3, "rad/s",
                           "angular velocity of " + body + ", global frame",
                           {0, 0, 0});
    return in;
}

connectors::Vector3 blockVector3(const double* values, Block block)
{
    return {values[block.first], values[block.first + 1],
            values[block.first + 2]};
}

connectors::Matrix3 blockMatrix3(const double* values, Block block)
{
    connectors::Matrix3 m;
    readBlockMatrix3(values, block, m);
    return m;
}

void readBlockMatrix3(const double* values, Block block, connectors::Matrix3& m)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            m(i, j) = values[block.first + 3 * i + j];
        }
    }
}

connectors::BodyKinematics bodyKinematics(const double* values,
                                          const BodyInputs& body)
{
    connectors::BodyKinematics k;
    k.p_WKo_W = blockVector3(values, body.r);
    k.R_WK = blockMatrix3(values, body.R);
    k.v_WKo_W = blockVector3(values, body.v);
    k.w_WK_W = blockVector3(values, body.omega);
    return k;
}

} // namespace fmuExport

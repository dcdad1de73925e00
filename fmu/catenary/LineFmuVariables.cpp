#include "LineFmuVariables.hpp"

#include <cmath>
#include <stdexcept>

#include "ModelDescription.hpp"

namespace lineFmu {

using fmuExport::Shape;

void declareAttachments(fmuExport::VariableTable& t, LineVariables& v)
{
    v.A_p = t.parameter("A.p", Shape::vector3, "m",
                        "fairlead on A, A's frame, from A's reference point",
                        {0, 0, 0});
    v.B_p
        = t.parameter("B.p", Shape::vector3, "m",
                      "anchor or fairlead on B, B's frame, from B's reference "
                      "point (a global point when B is the world)",
                      {0, 0, 0});
}

void declareBodies(fmuExport::VariableTable& t, LineVariables& v,
                   const std::vector<double>& B_r0)
{
    v.A = fmuExport::declareBodyInputs(t, "A", {0, 0, 0});
    v.B = fmuExport::declareBodyInputs(t, "B", B_r0);
}

void declareOutputs(fmuExport::VariableTable& t, LineVariables& v,
                    const LineDependencies& d)
{
    v.firstOutput = t.output("A.F", Shape::vector3, "N",
                             "force of the line on A, global frame", d.loads);
    t.output("A.M", Shape::vector3, "N.m",
             "moment of the line on A about A's reference point, global frame",
             d.loads);
    t.output("B.F", Shape::vector3, "N", "force of the line on B, global frame",
             d.loads);
    t.output("B.M", Shape::vector3, "N.m",
             "moment of the line on B about B's reference point, global frame",
             d.loads);
    t.output("length", Shape::scalar, "m",
             "distance between the attachment points (the chord)", d.length);
    t.output("lengthRate", Shape::scalar, "m/s",
             "time derivative of the chord length", d.lengthRate);
    t.output("tension", Shape::scalar, "N", "tension at the fairlead on A",
             d.loads);
    t.output("potentialEnergy", Shape::scalar, "J",
             "strain energy plus the potential of the line's weight (heights "
             "from z = 0)",
             d.energy);
    t.output("dissipatedPower", Shape::scalar, "W",
             "power dissipated in the line, never negative", d.dissipation);
    t.output("fairleadTension", Shape::scalar, "N",
             "tension at the fairlead on A", d.loads);
    t.output("anchorTension", Shape::scalar, "N",
             "tension at the anchor or fairlead on B", d.loads);
    t.output("groundedLength", Shape::scalar, "m",
             "unstretched length of line lying on the seabed", d.loads);
    v.H = t.output("H", Shape::scalar, "N",
                   "horizontal tension at the fairlead on A", d.loads);
    v.V = t.output("V", Shape::scalar, "N",
                   "vertical tension at the fairlead on A (pulls it down when "
                   "positive)",
                   d.loads);
    for (const char* axis : {"x", "y", "z"}) {
        for (int i = 1; i <= shapePoints; ++i) {
            t.output(std::string("shape.") + axis + "[" + std::to_string(i)
                         + "]",
                     Shape::scalar, "m",
                     std::string(axis) + " of point " + std::to_string(i)
                         + " of " + std::to_string(shapePoints)
                         + " along the line, from the fairlead on A (1) to "
                           "B ("
                         + std::to_string(shapePoints) + "), global frame",
                     d.loads);
        }
    }
}

std::vector<Block> positionBlocks(const LineVariables& v)
{
    return {v.A_p, v.B_p, v.A.r, v.A.R, v.B.r, v.B.R};
}

std::vector<Block> velocityBlocks(const LineVariables& v)
{
    return {v.A.v, v.A.omega, v.B.v, v.B.omega};
}

std::vector<Block> join(std::vector<Block> a, const std::vector<Block>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

void writeOutputs(double* values, const LineVariables& v,
                  const fmuExport::VariableTable& table,
                  const std::string& model, const LineOutputs& o)
{
    const connectors::ConnectorResult& r = o.loads;
    std::vector<double> out = {r.A.f_W[0],
                               r.A.f_W[1],
                               r.A.f_W[2],
                               r.A.m_Bo_W[0],
                               r.A.m_Bo_W[1],
                               r.A.m_Bo_W[2],
                               r.B.f_W[0],
                               r.B.f_W[1],
                               r.B.f_W[2],
                               r.B.m_Bo_W[0],
                               r.B.m_Bo_W[1],
                               r.B.m_Bo_W[2],
                               r.length,
                               r.lengthRate,
                               r.tension,
                               r.potentialEnergy,
                               r.dissipatedPower,
                               o.fairleadTension,
                               o.anchorTension,
                               o.groundedLength,
                               o.H,
                               o.V};
    if (o.shape.size() != std::size_t(shapePoints)) {
        throw std::logic_error(model + ": " + std::to_string(o.shape.size())
                               + " shape points, expected "
                               + std::to_string(shapePoints));
    }
    for (int axis = 0; axis < 3; ++axis) {
        for (const connectors::Vector3& p : o.shape) {
            out.push_back(p[axis]);
        }
    }
    const std::vector<fmuExport::ScalarVariable>& variables = table.variables();
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (!std::isfinite(out[i])) {
            throw std::range_error(model + ": output "
                                   + variables[v.firstOutput.first + i].name
                                   + " = " + fmuExport::formatDouble(out[i])
                                   + " is not finite (inputs or parameters "
                                     "too large)");
        }
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
        values[v.firstOutput.first + i] = out[i];
    }
}

} // namespace lineFmu

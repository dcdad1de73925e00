#include "ConnectorModel.hpp"

#include <cmath>
#include <stdexcept>

#include "ModelDescription.hpp"

namespace fmuExport {

namespace {

constexpr std::size_t outputCount = 17;

} // namespace

ConnectorModel::ConnectorModel(ModelIdentity identity)
    : Model(std::move(identity))
{
    A_p = table().parameter("A.p", Shape::vector3, "m",
                            "attachment point on A, A's frame, from A's "
                            "reference point",
                            {0, 0, 0});
    B_p = table().parameter("B.p", Shape::vector3, "m",
                            "attachment point on B, B's frame, from B's "
                            "reference point (a global point when B is the "
                            "world)",
                            {0, 0, 0});
    A = declareBodyInputs(table(), "A", {0, 0, 0});
    B = declareBodyInputs(table(), "B", {1, 0, 0});
}

void ConnectorModel::declareStartAtRest()
{
    table().booleanConstant("inputsStartAtRest",
                            "the start values of inputs and parameters are a "
                            "configuration where the connector exerts no load",
                            true);
}

void ConnectorModel::declareOutputs(const OutputDependencies& d)
{
    VariableTable& t = table();
    firstOutput_ = fmi2ValueReference(t.size());
    t.output("A.F", Shape::vector3, "N",
             "force of the connector on A, global frame", d.loads);
    t.output(
        "A.M", Shape::vector3, "N.m",
        "moment of the connector on A about A's reference point, global frame",
        d.loads);
    t.output("B.F", Shape::vector3, "N",
             "force of the connector on B, global frame", d.loads);
    t.output(
        "B.M", Shape::vector3, "N.m",
        "moment of the connector on B about B's reference point, global frame",
        d.loads);
    t.output("length", Shape::scalar, "m",
             "distance between the attachment points", d.length);
    t.output("lengthRate", Shape::scalar, "m/s",
             "time derivative of the length", d.lengthRate);
    t.output(
        "tension", Shape::scalar, "N",
        "axial force, positive when the connector pulls the bodies together",
        d.tension);
    t.output("potentialEnergy", Shape::scalar, "J",
             "energy stored in the connector", d.potentialEnergy);
    t.output(
        "dissipatedPower", Shape::scalar, "W",
        "power dissipated by the connector (removed from the bodies and not "
        "stored), never negative",
        d.dissipatedPower);
}

std::vector<Block> ConnectorModel::positionBlocks() const
{
    return {A_p, B_p, A.r, A.R, B.r, B.R};
}

std::vector<Block> ConnectorModel::velocityBlocks() const
{
    return {A.v, A.omega, B.v, B.omega};
}

std::vector<Block> ConnectorModel::join(std::vector<Block> a,
                                        const std::vector<Block>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

double ConnectorModel::scalar(const double* values, Block block)
{
    return values[block.first];
}

connectors::Vector3 ConnectorModel::vector3(const double* values, Block block)
{
    return blockVector3(values, block);
}

void ConnectorModel::computeOutputs(double* values) const
{
    const connectors::ConnectorResult r = evaluate(
        values, bodyKinematics(values, A), bodyKinematics(values, B));
    const double out[outputCount]
        = {r.A.f_W[0],       r.A.f_W[1],    r.A.f_W[2],    r.A.m_Bo_W[0],
           r.A.m_Bo_W[1],    r.A.m_Bo_W[2], r.B.f_W[0],    r.B.f_W[1],
           r.B.f_W[2],       r.B.m_Bo_W[0], r.B.m_Bo_W[1], r.B.m_Bo_W[2],
           r.length,         r.lengthRate,  r.tension,     r.potentialEnergy,
           r.dissipatedPower};
    const std::vector<ScalarVariable>& variables
        = this->variables().variables();
    for (std::size_t i = 0; i < outputCount; ++i) {
        if (!std::isfinite(out[i])) {
            throw std::range_error(identity().modelIdentifier + ": output "
                                   + variables[firstOutput_ + i].name + " = "
                                   + formatDouble(out[i])
                                   + " is not finite (inputs or parameters "
                                     "too large)");
        }
    }
    for (std::size_t i = 0; i < outputCount; ++i) {
        values[firstOutput_ + i] = out[i];
    }
}

} // namespace fmuExport

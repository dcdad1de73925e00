#include "ConnectorModel.hpp"

#include <cmath>
#include <stdexcept>

#include "ModelDescription.hpp"

namespace fmuExport {

namespace {

constexpr std::size_t outputCount = 17;

ConnectorModel::BodyInputs declareBody(VariableTable& table,
                                       const std::string& body,
                                       const std::vector<double>& r0)
{
    ConnectorModel::BodyInputs in;
    in.r = table.input(
        body + ".r", Shape::vector3, "m",
        "position of " + body + "'s reference point, global frame", r0);
    in.R =
        table.input(body + ".R", Shape::matrix3, "1",
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
    A = declareBody(table(), "A", {0, 0, 0});
    B = declareBody(table(), "B", {1, 0, 0});
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
    return {values[block.first], values[block.first + 1],
            values[block.first + 2]};
}

connectors::BodyKinematics
ConnectorModel::kinematics(const double* values, const BodyInputs& body) const
{
    connectors::BodyKinematics k;
    k.p_WBo_W = vector3(values, body.r);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            k.R_WB(i, j) = values[body.R.first + 3 * i + j];
        }
    }
    k.v_WBo_W = vector3(values, body.v);
    k.w_WB_W = vector3(values, body.omega);
    return k;
}

void ConnectorModel::computeOutputs(double* values) const
{
    const connectors::ConnectorResult r =
        evaluate(values, kinematics(values, A), kinematics(values, B));
    const double out[outputCount] = {
        r.A.f_W[0],       r.A.f_W[1],    r.A.f_W[2],    r.A.m_Bo_W[0],
        r.A.m_Bo_W[1],    r.A.m_Bo_W[2], r.B.f_W[0],    r.B.f_W[1],
        r.B.f_W[2],       r.B.m_Bo_W[0], r.B.m_Bo_W[1], r.B.m_Bo_W[2],
        r.length,         r.lengthRate,  r.tension,     r.potentialEnergy,
        r.dissipatedPower};
    const std::vector<ScalarVariable>& variables =
        this->variables().variables();
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

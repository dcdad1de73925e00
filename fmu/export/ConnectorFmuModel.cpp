#include "ConnectorFmuModel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ModelDescription.hpp"
#include "common/ConnectorError.hpp"

namespace fmuExport {

namespace {

//- A.F, A.M, B.F, B.M (three each) and the five diagnostics
constexpr std::size_t interfaceOutputCount = 17;

} // namespace

ConnectorFmuModel::ConnectorFmuModel(ModelIdentity identity,
                                     ConnectorWording wording)
    : Model(std::move(identity)), wording_(std::move(wording))
{
    A_p = table().parameter(
        "A.p", Shape::vector3, "m",
        wording_.A_p + ", A's frame, from A's reference point", {0, 0, 0});
    B_p = table().parameter("B.p", Shape::vector3, "m",
                            wording_.B_p
                                + ", B's frame, from B's reference point (a "
                                  "global point when B is the world)",
                            {0, 0, 0});
}

void ConnectorFmuModel::declareBodies(const std::vector<double>& B_p0)
{
    table().setStart(B_p, B_p0);
    A = declareBodyInputs(table(), "A", {0, 0, 0});
    B = declareBodyInputs(table(), "B", {0, 0, 0});
    bodiesDeclared_ = true;
}

void ConnectorFmuModel::declareStartAtRest()
{
    table().booleanConstant("inputsStartAtRest",
                            "the start values of inputs and parameters are a "
                            "configuration where the connector exerts no load",
                            true);
}

void ConnectorFmuModel::declareOutputs(const OutputDependencies& d)
{
    if (!bodiesDeclared_) {
        throw std::logic_error(identity().modelIdentifier
                               + ": declareOutputs before declareBodies");
    }
    VariableTable& t = table();
    const std::string& noun = wording_.noun;
    firstOutput_ = fmi2ValueReference(t.size());
    outputsDeclared_ = true;
    for (const std::string body : {"A", "B"}) {
        t.output(body + ".F", Shape::vector3, "N",
                 "force of the " + noun + " on " + body + ", global frame",
                 d.loads);
        t.output(body + ".M", Shape::vector3, "N.m",
                 "moment of the " + noun + " on " + body + " about " + body
                     + "'s reference point, global frame",
                 d.loads);
    }
    t.output("length", Shape::scalar, "m", wording_.length, d.length);
    t.output("lengthRate", Shape::scalar, "m/s", wording_.lengthRate,
             d.lengthRate);
    t.output("tension", Shape::scalar, "N", wording_.tension, d.tension);
    t.output("potentialEnergy", Shape::scalar, "J", wording_.potentialEnergy,
             d.potentialEnergy);
    t.output("dissipatedPower", Shape::scalar, "W", wording_.dissipatedPower,
             d.dissipatedPower);
}

Block ConnectorFmuModel::extraOutput(const std::string& name, Shape shape,
                                     const std::string& unit,
                                     const std::string& description,
                                     const std::vector<Block>& dependsOn)
{
    VariableTable& t = table();
    if (!outputsDeclared_
        || t.size() != firstOutput_ + interfaceOutputCount + extraCount_) {
        throw std::logic_error(identity().modelIdentifier + ": extra output "
                               + name
                               + " does not follow the interface outputs");
    }
    const Block block = t.output(name, shape, unit, description, dependsOn);
    extraCount_ += block.size;
    return block;
}

Block ConnectorFmuModel::extraLocal(const std::string& name, Shape shape,
                                    const std::string& unit,
                                    const std::string& description)
{
    VariableTable& t = table();
    const std::size_t outputsEnd
        = firstOutput_ + interfaceOutputCount + extraCount_;
    if (!outputsDeclared_
        || t.size()
            != (localCount_ == 0 ? outputsEnd : firstLocal_ + localCount_)) {
        throw std::logic_error(identity().modelIdentifier + ": local " + name
                               + " does not follow the outputs and locals");
    }
    const Block block = t.local(name, shape, unit, description);
    firstLocal_ = localCount_ == 0 ? block.first : firstLocal_;
    localCount_ += block.size;
    return block;
}

std::vector<Block> ConnectorFmuModel::positionBlocks() const
{
    return {A_p, B_p, A.r, A.R, B.r, B.R};
}

std::vector<Block> ConnectorFmuModel::velocityBlocks() const
{
    return {A.v, A.omega, B.v, B.omega};
}

ConnectorFmuModel::OutputDependencies
ConnectorFmuModel::pointToPointDependencies(const std::vector<Block>& law) const
{
    const std::vector<Block> positions = positionBlocks();
    const std::vector<Block> motion = join(positions, velocityBlocks());
    OutputDependencies d;
    d.loads = join(motion, law);
    d.length = positions;
    d.lengthRate = motion;
    d.tension = d.loads;
    d.potentialEnergy = {};
    d.dissipatedPower = d.loads;
    return d;
}

std::vector<Block> ConnectorFmuModel::join(std::vector<Block> a,
                                           const std::vector<Block>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

bool ConnectorFmuModel::flag(const double* values, Block block) const
{
    const double value = scalar(values, block);
    if (value != 0.0 && value != 1.0) {
        const std::string& name = variables().variables()[block.first].name;
        throw connectors::ParameterError(
            connectors::Refusal::outOfRange, name,
            identity().modelIdentifier + ": parameter " + name + " = "
                + connectors::formatValue(value)
                + " is out of range (allowed: 0 or 1)");
    }
    return value == 1.0;
}

double ConnectorFmuModel::scalar(const double* values, Block block)
{
    return values[block.first];
}

connectors::Vector3 ConnectorFmuModel::vector3(const double* values,
                                               Block block)
{
    return blockVector3(values, block);
}

void ConnectorFmuModel::computeOutputs(double* values) const
{
    writeOutputs(
        values,
        evaluate(values, bodyKinematics(values, A), bodyKinematics(values, B)));
}

void ConnectorFmuModel::writeOutputs(double* values,
                                     const ConnectorOutputs& outputs) const
{
    // all checked before any is written (checkTrailing checks the counts)
    double interface[interfaceOutputCount];
    interfaceValues(outputs.loads, interface);
    check(interface, firstOutput_, interfaceOutputCount);
    checkTrailing(outputs, 0);
    double* out = std::copy(interface, interface + interfaceOutputCount,
                            values + firstOutput_);
    std::copy(outputs.extra.begin(), outputs.extra.end(), out);
    std::copy(outputs.locals.begin(), outputs.locals.end(),
              values + firstLocal_);
}

void ConnectorFmuModel::interfaceValues(const connectors::ConnectorResult& r,
                                        double* v)
{
    const double interface[interfaceOutputCount]
        = {r.A.f_W[0],       r.A.f_W[1],    r.A.f_W[2],    r.A.m_Ko_W[0],
           r.A.m_Ko_W[1],    r.A.m_Ko_W[2], r.B.f_W[0],    r.B.f_W[1],
           r.B.f_W[2],       r.B.m_Ko_W[0], r.B.m_Ko_W[1], r.B.m_Ko_W[2],
           r.length,         r.lengthRate,  r.tension,     r.potentialEnergy,
           r.dissipatedPower};
    std::copy(interface, interface + interfaceOutputCount, v);
}

void ConnectorFmuModel::writeLeadingOutputs(
    double* values, const connectors::ConnectorResult& r, const double* extra,
    std::size_t n) const
{
    double interface[interfaceOutputCount];
    interfaceValues(r, interface);
    check(interface, firstOutput_, interfaceOutputCount);
    check(extra, firstOutput_ + fmi2ValueReference(interfaceOutputCount), n);
    double* out = std::copy(interface, interface + interfaceOutputCount,
                            values + firstOutput_);
    std::copy(extra, extra + n, out);
}

void ConnectorFmuModel::writeTrailingOutputs(double* values,
                                             const ConnectorOutputs& outputs,
                                             std::size_t n) const
{
    checkTrailing(outputs, n);
    std::copy(outputs.extra.begin() + std::ptrdiff_t(n), outputs.extra.end(),
              values + firstOutput_ + interfaceOutputCount + n);
    std::copy(outputs.locals.begin(), outputs.locals.end(),
              values + firstLocal_);
}

Block ConnectorFmuModel::trailingOutputs(std::size_t n) const
{
    const fmi2ValueReference first
        = firstOutput_ + fmi2ValueReference(interfaceOutputCount + n);
    if (localCount_ != 0
        && firstLocal_ != firstOutput_ + interfaceOutputCount + extraCount_) {
        throw std::logic_error(identity().modelIdentifier
                               + ": the locals do not follow the outputs");
    }
    return {first, extraCount_ - n + localCount_};
}

void ConnectorFmuModel::checkTrailing(const ConnectorOutputs& outputs,
                                      std::size_t n) const
{
    const std::string& model = identity().modelIdentifier;
    if (outputs.extra.size() != extraCount_
        || outputs.locals.size() != localCount_ || n > extraCount_) {
        throw std::logic_error(
            model + ": " + std::to_string(outputs.extra.size())
            + " extra output values and "
            + std::to_string(outputs.locals.size()) + " local values, expected "
            + std::to_string(extraCount_) + " and "
            + std::to_string(localCount_));
    }
    check(outputs.extra.data() + n,
          firstOutput_ + fmi2ValueReference(interfaceOutputCount + n),
          extraCount_ - n);
    check(outputs.locals.data(), firstLocal_, localCount_, "local");
}

void ConnectorFmuModel::check(const double* v, fmi2ValueReference first,
                              std::size_t n, const char* kind) const
{
    // checked in one pass, and searched for the value to name only when
    // one is not finite
    bool all = true;
    for (std::size_t i = 0; i < n; ++i) {
        all &= std::isfinite(v[i]);
    }
    if (all) {
        return;
    }
    const std::size_t i = std::size_t(
        std::find_if(v, v + n, [](double x) { return !std::isfinite(x); }) - v);
    throw std::range_error(identity().modelIdentifier + ": " + kind + " "
                           + variables().variables()[first + i].name + " = "
                           + formatDouble(v[i])
                           + " is not finite (inputs or parameters too "
                             "large)");
}

} // namespace fmuExport

// mooringLine.fmu: connectors::MooringLine, a dynamic lumped-mass line
// integrated inside each fmi2DoStep (the implicit trapezoidal rule, or
// CVODE), behind the connector FMU interface. The variable table below is
// the only list of its variables.
//
// Internal state (Model::internalState): time, end positions, velocities
// (the start of the next step's Hermite path) and accelerations, the
// position and velocity of every free node, and the trapezoidal rule's
// factorised Newton matrix kept from step to step; then the start time of the
// last step, its flow inputs (the flow's acceleration over the next
// step is their change) and the flow's acceleration it took; then the
// energy account summed since the start (the energy outputs,
// EnergyVariables.hpp; zero with energyAccount = 0).
//
// A step computes the loads and fairleadTension, anchorTension,
// groundedLength, H and V; the shape, the sections' values and the energy
// outputs are computed from the state when fmi2GetReal first asks for one
// of them after the step (deferredOutputs, completeOutputs), the same
// numbers as the step would have computed. It is saved, restored and
// serialized with the FMU state; each step starts the integrator from it,
// so a step repeated after fmi2SetFMUstate gives the same outputs to the
// bit.
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "EnergyVariables.hpp"
#include "FlowHistory.hpp"
#include "LawDescription.hpp"
#include "LineFmuModel.hpp"
#include "ScalarParameters.hpp"
#include "SectionVariables.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/MooringLine.hpp"

namespace {

using fmuExport::Block;
using fmuExport::Shape;
using mooringLineFmu::Scalar;
using mooringLineFmu::ScalarBlocks;
using mooringLineFmu::scalarCount;
using mooringLineFmu::scalars;

class MooringLineModel final : public fmuExport::LineFmuModel {
public:
    MooringLineModel();

    void setParameters(const double* values) override
    {
        law_.build(parameters(values));
        flowInertia(values); // 0, 1 or 2, refused otherwise
    }

    //- The shape, the sections' values and the energy outputs: computed
    //  when read (fmi2GetReal), not by every step
    fmuExport::Block deferredOutputs() const override
    {
        return trailingOutputs(leadingLineOutputs);
    }
    void completeOutputs(double* values) const override;

    void initializeState(const double* values, double time) override;
    void doStep(double* values, double time, double h) override;
    std::vector<double> internalState() const override
    {
        std::vector<double> out;
        saveInternalState(out);
        return out;
    }
    void saveInternalState(std::vector<double>& out) const override;
    void setInternalState(const double* values,
                          const std::vector<double>& state) override;

protected:
    fmuExport::ConnectorOutputs
    evaluate(const double* values, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const override;

private:
    //- The extra outputs a step writes: fairleadTension, anchorTension,
    //  groundedLength, H, V (the first of LineFmuModel's)
    static constexpr std::size_t leadingLineOutputs = 5;

    connectors::MooringLineParameters parameters(const double* values) const;
    //- Declare the inputs <base>x/y/z[k] at the shape points, x of every
    //  point first; their blocks
    std::vector<fmuExport::Block> declareShapeInputs(const std::string& base,
                                                     const std::string& unit,
                                                     const std::string& what,
                                                     const std::string& note);
    //- The outputs of the law's output `out` and the energy account
    //  summed since the start `energy`
    fmuExport::ConnectorOutputs
    lineOutputs(const connectors::MooringLineOutput& out,
                const connectors::LineEnergy& energy) const;

    //- The inputs from `first` (x of the shape points, then y, then z)
    //  as points from P to Q; empty when all are zero
    std::vector<connectors::Vector3>
    shapeInputs(const double* values, fmi2ValueReference first) const;
    //- The flow inputs shape.U
    std::vector<connectors::Vector3> flow(const double* values) const
    {
        return shapeInputs(values, flow_);
    }
    //- How the flow's acceleration is taken: 0 not, 1 the change of the
    //  inputs shape.U, 2 the inputs shape.A
    int flowInertia(const double* values) const;
    //- The flow's acceleration over a step from `time` with the flow
    //  inputs `U` (flowInertia 1: FlowHistory; 2: the inputs shape.A; 0:
    //  none)
    std::vector<connectors::Vector3>
    flowAcceleration(const double* values,
                     const std::vector<connectors::Vector3>& U,
                     double time) const
    {
        switch (flowInertia(values)) {
        case 1:
            return lastFlow_.acceleration(U, time);
        case 2:
            return shapeInputs(values, flowAcceleration_);
        default:
            return {};
        }
    }

    //- The flow inputs of the last step and its start time (at the start:
    //  those at fmi2ExitInitializationMode and its time)
    mooringLineFmu::FlowHistory lastFlow_ {shapePoints};
    Block flowInertia_, energyAccount_;

    ScalarBlocks p_;
    Block currentSurface_, currentSeabed_;
    mooringLineFmu::SectionVariables sections_;
    //- First of the inputs shape.Ux[1..], shape.Uy[1..], shape.Uz[1..],
    //  and of shape.Ax[1..], shape.Ay[1..], shape.Az[1..]
    fmi2ValueReference flow_ = 0, flowAcceleration_ = 0;
    fmuExport::BuiltLaw<connectors::MooringLine> law_;
    std::optional<connectors::MooringLineState> state_;
    //- The law's energy account summed over the steps since the start
    connectors::LineEnergy energy_;
};

MooringLineModel::MooringLineModel()
    : LineFmuModel(
        {"mooringLine",
         "Dynamic lumped-mass mooring line between a body and a seabed "
         "anchor, or between two bodies (integrated inside each step)",
         "1.0.0", mooringLineFmu::lawHtml})
{
    fmuExport::VariableTable& t = table();
    for (const Scalar& s : scalars) {
        p_.*s.block = t.parameter(s.name, Shape::scalar, s.unit, s.description,
                                  {s.start});
    }
    currentSurface_ = t.parameter(
        "current.surface", Shape::vector3, "m/s",
        "current at waterLevel, global frame (linear in z down to "
        "current.seabed at the seabed, the height of B.p)",
        {0.0, 0.0, 0.0});
    currentSeabed_
        = t.parameter("current.seabed", Shape::vector3, "m/s",
                      "current at the seabed (the height of B.p), global frame",
                      {0.0, 0.0, 0.0});
    sections_.declareParameters(t);
    declareBodies({1, 0, 0});
    const std::vector<Block> flowInputs = declareShapeInputs(
        "shape.U", "m/s", "water velocity", "added to the current");
    flow_ = flowInputs.front().first;
    const std::vector<Block> positions = positionBlocks();
    const std::vector<Block> motion = join(positions, velocityBlocks());
    const Block all {(p_.*scalars[0].block).first, scalarCount};
    OutputDependencies d;
    d.loads = join(
        join(motion,
             {all, currentSurface_, currentSeabed_, sections_.parameters()}),
        flowInputs);
    d.length = positions;
    d.lengthRate = motion;
    d.tension = d.loads;
    d.potentialEnergy = join(positions, {all, sections_.parameters()});
    d.dissipatedPower = d.loads;
    declareLineOutputs(d);
    for (const auto& o : mooringLineFmu::SectionVariables::outputs()) {
        extraOutput(o.name, Shape::scalar, o.unit, o.description, d.loads);
    }
    for (const auto& o : mooringLineFmu::energyVariables::outputs(
             mooringLineFmu::maxSections)) {
        extraOutput(o.name, Shape::scalar, o.unit, o.description, d.loads);
    }
    declareShapeSections();
    // declared last: the variables above keep their value references
    flowInertia_ = t.parameter(
        "flowInertia", Shape::scalar, "1",
        "1 (default): the flow's acceleration, the change of the inputs "
        "shape.U over the previous step, acts on the line as (1 + Ca) rho V "
        "dU/dt, normal and tangential (Froude-Krylov and added mass); 2: the "
        "inputs shape.A are that acceleration; 0: none",
        {1.0});
    energyAccount_ = t.parameter(
        "energyAccount", Shape::scalar, "1",
        "1 (default): the energy outputs (fairleadWork, anchorWork, "
        "waterWork, addedMassWork, the dissipated energies) are integrated "
        "every step; 0: they are not, and stay 0 (a step costs about 6 % "
        "less; the motion, the loads and kineticEnergy are the same)",
        {1.0});
    flowAcceleration_
        = declareShapeInputs("shape.A", "m/s2", "water acceleration",
                             "at the start of the step (used with "
                             "flowInertia = 2)")
              .front()
              .first;
}

std::vector<Block> MooringLineModel::declareShapeInputs(const std::string& base,
                                                        const std::string& unit,
                                                        const std::string& what,
                                                        const std::string& note)
{
    std::vector<Block> blocks;
    const std::string n = std::to_string(shapePoints);
    for (const char* axis : {"x", "y", "z"}) {
        for (int i = 1; i <= shapePoints; ++i) {
            const std::string point = std::to_string(i);
            blocks.push_back(table().input(
                base + axis + "[" + point + "]", Shape::scalar, unit,
                what + ", " + axis + " (global frame), at point " + point
                    + " of " + n + " of the shape outputs of the previous "
                    + "step, " + note,
                {0.0}));
        }
    }
    return blocks;
}

int MooringLineModel::flowInertia(const double* values) const
{
    const double value = scalar(values, flowInertia_);
    if (value != 0.0 && value != 1.0 && value != 2.0) {
        throw connectors::ParameterError(
            connectors::Refusal::outOfRange, "flowInertia",
            "mooringLine: parameter flowInertia = "
                + connectors::formatValue(value)
                + " is out of range (allowed: 0, 1 or 2)");
    }
    return int(value);
}

connectors::MooringLineParameters
MooringLineModel::parameters(const double* values) const
{
    const double segments = scalar(values, p_.segments);
    if (!(segments >= 2.0 && segments <= 1000.0
          && segments == std::floor(segments))) {
        throw connectors::ParameterError(
            connectors::Refusal::outOfRange, "segments",
            "mooringLine: parameter segments = "
                + connectors::formatValue(segments)
                + " is out of range (allowed: an integer from 2 to 1000)");
    }
    const auto value = [&](Block b) { return scalar(values, b); };
    connectors::MooringLineParameters p;
    p.p_AoP_A = vector3(values, A_p);
    p.p_BoQ_B = vector3(values, B_p);
    p.length = value(p_.length);
    p.EA = value(p_.EA);
    p.axialDamping = value(p_.axialDamping);
    p.massPerLength = value(p_.massPerLength);
    p.diameter = value(p_.diameter);
    p.waterDensity = value(p_.waterDensity);
    p.gravity = value(p_.gravity);
    p.normalDrag = value(p_.normalDrag);
    p.tangentialDrag = value(p_.tangentialDrag);
    p.normalAddedMass = value(p_.normalAddedMass);
    p.tangentialAddedMass = value(p_.tangentialAddedMass);
    p.seabedContact = flag(values, p_.seabedContact);
    p.seabedStiffness = value(p_.seabedStiffness);
    p.seabedDamping = value(p_.seabedDamping);
    p.segments = int(segments);
    p.relativeTolerance = value(p_.relativeTolerance);
    p.absoluteTolerance = value(p_.absoluteTolerance);
    p.hermiteEnds = flag(values, p_.hermiteEnds);
    p.integrator = flag(values, p_.integrator)
        ? connectors::MooringLineParameters::Integrator::cvode
        : connectors::MooringLineParameters::Integrator::trapezoid;
    p.maxStep = value(p_.maxStep);
    p.freeSurface = flag(values, p_.freeSurface);
    p.waterLevel = value(p_.waterLevel);
    p.seabedFriction = value(p_.seabedFriction);
    p.frictionVelocity = value(p_.frictionVelocity);
    p.axialFrictionRatio = value(p_.axialFrictionRatio);
    p.staticFrictionScale = value(p_.staticFrictionScale);
    p.endInertia = flag(values, p_.endInertia);
    p.energyAccount = flag(values, energyAccount_);
    p.currentSurface = vector3(values, currentSurface_);
    p.currentSeabed = vector3(values, currentSeabed_);
    sections_.read(values, variables(), p);
    return p;
}

std::vector<connectors::Vector3>
MooringLineModel::shapeInputs(const double* values,
                              fmi2ValueReference first) const
{
    std::vector<connectors::Vector3> points(
        static_cast<std::size_t>(shapePoints), connectors::Vector3::Zero());
    bool any = false;
    for (int k = 0; k < shapePoints; ++k) {
        for (int axis = 0; axis < 3; ++axis) {
            const double u = values[first + axis * shapePoints + k];
            points[std::size_t(k)][axis] = u;
            any = any || u != 0.0;
        }
    }
    if (!any) {
        points.clear();
    }
    return points;
}

fmuExport::ConnectorOutputs
MooringLineModel::lineOutputs(const connectors::MooringLineOutput& m,
                              const connectors::LineEnergy& energy) const
{
    fmuExport::LineOutputs o;
    o.loads = m.loads;
    o.fairleadTension = m.fairleadTension;
    o.anchorTension = m.anchorTension;
    o.groundedLength = m.groundedLength;
    o.H = m.H;
    o.V = m.V;
    o.shape = m.shape;
    o.tension = m.shapeTension;
    o.sectionLengths
        = mooringLineFmu::SectionVariables::lengths(law_.get().parameters());
    fmuExport::ConnectorOutputs all = outputs(o);
    const std::vector<double> sections
        = mooringLineFmu::SectionVariables::values(m);
    all.extra.insert(all.extra.end(), sections.begin(), sections.end());
    const std::vector<double> energies
        = mooringLineFmu::energyVariables::values(m, energy,
                                                  mooringLineFmu::maxSections);
    all.extra.insert(all.extra.end(), energies.begin(), energies.end());
    return all;
}

fmuExport::ConnectorOutputs
MooringLineModel::evaluate(const double* values,
                           const connectors::BodyKinematics& A,
                           const connectors::BodyKinematics& B) const
{
    const connectors::MooringLine& law = law_.get();
    if (state_) {
        // as the step from here will see the water
        const std::vector<connectors::Vector3> U = flow(values);
        return lineOutputs(
            law.evaluate(*state_, A, B, shapePoints, U,
                         flowAcceleration(values, U, state_->time)),
            energy_);
    }
    // Before fmi2ExitInitializationMode: the line at rest in its start shape
    return lineOutputs(law.evaluate(law.initialState(A, B, 0.0), A, B,
                                    shapePoints, flow(values)),
                       connectors::LineEnergy());
}

void MooringLineModel::initializeState(const double* values, double time)
{
    state_
        = law_.get().initialState(fmuExport::bodyKinematics(values, A),
                                  fmuExport::bodyKinematics(values, B), time);
    lastFlow_.record(time, flow(values));
    energy_.clear(law_.get().parameters().sections.size() + 1);
}

void MooringLineModel::doStep(double* values, double time, double h)
{
    if (!state_) {
        throw std::logic_error("mooringLine: fmi2DoStep before the line was "
                               "initialised");
    }
    connectors::MooringLine& law = law_.get();
    const connectors::BodyKinematics bodyA
        = fmuExport::bodyKinematics(values, A);
    const connectors::BodyKinematics bodyB
        = fmuExport::bodyKinematics(values, B);
    const std::vector<connectors::Vector3> water = flow(values);
    const std::vector<connectors::Vector3> a
        = flowAcceleration(values, water, time);
    connectors::MooringLineState next = *state_;
    law.advance(next, bodyA, bodyB, h, water, a);
    // the loads and the line's scalars; the rest when read
    // (completeOutputs)
    const connectors::MooringLineOutput m
        = law.evaluate(next, bodyA, bodyB, 0, water, a,
                       connectors::MooringLine::Detail::loads);
    const double line[leadingLineOutputs]
        = {m.fairleadTension, m.anchorTension, m.groundedLength, m.H, m.V};
    writeLeadingOutputs(values, m.loads, line, leadingLineOutputs);
    state_ = std::move(next);
    if (law.parameters().energyAccount) {
        energy_ += law.stepEnergy();
    }
    lastFlow_.record(time, water, a);
}

void MooringLineModel::completeOutputs(double* values) const
{
    // as the last step evaluated its loads: its flow inputs (in `values`)
    // and acceleration
    const connectors::BodyKinematics bodyA
        = fmuExport::bodyKinematics(values, A);
    const connectors::BodyKinematics bodyB
        = fmuExport::bodyKinematics(values, B);
    const connectors::MooringLineOutput m = state_
        ? law_.get().evaluate(*state_, bodyA, bodyB, shapePoints, flow(values),
                              lastFlow_.stepAcceleration())
        : law_.get().evaluate(law_.get().initialState(bodyA, bodyB, 0.0), bodyA,
                              bodyB, shapePoints, flow(values));
    writeTrailingOutputs(values, lineOutputs(m, energy_), leadingLineOutputs);
}

void MooringLineModel::saveInternalState(std::vector<double>& out) const
{
    out.clear();
    if (!state_) {
        return;
    }
    // the line's state, then the last step's start time, flow inputs and
    // flow acceleration (3 values a point each, all zero for none), then
    // the energy account (4 + 3 per section)
    state_->serialize(out);
    lastFlow_.save(out);
    energy_.appendValues(out);
}

void MooringLineModel::setInternalState(const double*,
                                        const std::vector<double>& state)
{
    if (state.empty()) {
        state_.reset();
        energy_ = connectors::LineEnergy();
        return;
    }
    const connectors::MooringLineParameters& p = law_.get().parameters();
    const std::size_t line
        = connectors::MooringLineState::serializedSize(p.totalSegments());
    const std::size_t sections = p.sections.size() + 1;
    const std::size_t energy = 4 + 3 * sections;
    const std::size_t all = line + lastFlow_.size() + energy;
    if (state.size() != all) {
        throw std::invalid_argument(
            "mooringLine: a saved state of " + std::to_string(state.size())
            + " values does not fit a line of "
            + std::to_string(p.totalSegments()) + " segments in "
            + std::to_string(sections) + " sections (" + std::to_string(all)
            + " values: " + std::to_string(line) + " of the line, 1 + 6 x "
            + std::to_string(shapePoints) + " of the last step's flow, "
            + std::to_string(energy) + " of the energy account)");
    }
    state_ = connectors::MooringLineState::deserialize(
        std::vector<double>(state.begin(),
                            state.begin() + std::ptrdiff_t(line)),
        p);
    lastFlow_.restore(state.data() + line);
    energy_ = connectors::LineEnergy::fromValues(
        state.data() + line + lastFlow_.size(), energy, sections);
}

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<MooringLineModel>();
}

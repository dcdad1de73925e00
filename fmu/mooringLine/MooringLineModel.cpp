// mooringLine.fmu: connectors::MooringLine, a dynamic lumped-mass line
// integrated inside each fmi2DoStep (the implicit trapezoidal rule, or
// CVODE), behind the connector FMU interface. The variable table below is
// the only list of its variables.
//
// Internal state (Model::internalState): time, end positions, velocities
// (the start of the next step's Hermite path) and accelerations, and the
// position
// and velocity of every free node. It is saved, restored and
// serialized with the FMU state; each step starts the integrator from it,
// so a step repeated after fmi2SetFMUstate gives the same outputs to the
// bit.
#include <cmath>
#include <optional>

#include "LineFmuModel.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/MooringLine.hpp"

namespace {

using fmuExport::Block;
using fmuExport::Shape;

const char* const lawHtml = R"(<p>A dynamic lumped-mass mooring line (after
MoorDyn) between the fairlead P (<code>A.p</code> on A) and Q
(<code>B.p</code> on B): an anchor on the seabed (<code>seabedContact</code>
= 1, the seabed is the horizontal plane through Q) or a fairlead on a second
body. N = <code>segments</code> segments of unstretched length L/N; node 0 is
Q, node N is P, the N-1 free nodes carry one segment's mass each:</p>
<pre>
segment tension  T = EA max(e, 0) + axialDamping de/dt,  e = strain
node             (mass + added mass) a = T_i q_i - T_i-1 q_i-1 + E_i
E_i              = -(weight - buoyancy) + seabed penalty and friction
                   + Morison drag relative to the water (current + flow)
A.F = -T_N-1 q_N-1 + E_N,   B.F = T_0 q_0 + E_0   (the ends' half segments)
</pre>
<p>The water moves with the current profile (<code>current.surface</code>
at <code>waterLevel</code>, <code>current.seabed</code> at the height of
B.p, linear between) plus the inputs <code>shape.Ux/Uy/Uz[k]</code>: the
water velocity at the points of the shape outputs of the previous step,
held over the step and interpolated along the line.
<code>freeSurface</code> = 1 removes buoyancy, drag and added mass above
<code>waterLevel</code>. <code>seabedFriction</code> adds Coulomb friction
on the seabed, regularised below <code>frictionVelocity</code>.</p>
<p>Inside each fmi2DoStep the node states are integrated by the implicit
trapezoidal rule (<code>integrator</code> = 0, the default: one step per
coupling step, or substeps no longer than <code>maxStep</code>, each one
Newton solve with the line's block-tridiagonal matrix, a step halved where
its predictor misses) or by SUNDIALS CVODE (<code>integrator</code> = 1:
BDF, banded direct solver, tolerances <code>relativeTolerance</code>,
<code>absoluteTolerance</code>, restarted at every step), the ends moving
along the cubic Hermite path through their positions and velocities at the
start of the step (saved in the FMU state) and at its end (the inputs): set
the inputs to the end-of-step positions and velocities before fmi2DoStep.
Either integrator starts each step from the node states alone, so a step
repeated from a saved FMU state is identical to the uninterrupted one. The
line starts at rest in the static equilibrium of its own discrete equations
(found by Newton from the quasi-static catenary shape through the
attachment points) at fmi2ExitInitializationMode. SUNDIALS is linked into
the binary: the FMU needs nothing installed beside it. Details:
connectors/mooringLine/README.md.</p>)";

struct Scalar {
    const char* name;
    const char* unit;
    const char* description;
    double start;
};

// Model-scale start values: a 1.5 m line of 0.5 kg/m between two points
// 1 m apart, in two-body mode
const Scalar scalars[] = {
    {"unstretchedLength", "m",
     "unstretched length L, > 0, at least the ends' distance at the start "
     "over 1.3",
     1.5},
    {"EA", "N", "axial stiffness, > 0", 1e4},
    {"axialDamping", "N.s", "axial damping BA (tension per strain rate), >= 0",
     10.0},
    {"massPerLength", "kg/m", "dry mass per unstretched length, > 0", 0.5},
    {"diameter", "m",
     "volume-equivalent diameter (buoyancy, drag, added mass, seabed contact), "
     ">= 0 (> 0 with seabedContact = 1)",
     0.01},
    {"waterDensity", "kg/m3", "water density, >= 0", 1025.0},
    {"gravity", "m/s2", "gravitational acceleration (along -z), >= 0", 9.81},
    {"normalDrag", "1", "transverse drag coefficient Cdn, >= 0", 1.2},
    {"tangentialDrag", "1", "tangential drag coefficient Cdt, >= 0", 0.05},
    {"normalAddedMass", "1", "transverse added-mass coefficient Can, >= 0",
     1.0},
    {"tangentialAddedMass", "1", "tangential added-mass coefficient Cat, >= 0",
     0.0},
    {"seabedContact", "1",
     "1: B.p is an anchor on the seabed (the horizontal plane through it); 0: no "
     "seabed",
     0.0},
    {"seabedStiffness", "Pa/m",
     "seabed penalty stiffness per contact area, >= 0 (> 0 with "
     "seabedContact = 1)",
     3e6},
    {"seabedDamping", "Pa.s/m", "seabed penalty damping per contact area, >= 0",
     3e5},
    {"segments", "1", "number of segments N, an integer from 2 to 1000", 20.0},
    {"relativeTolerance", "1", "CVODE relative tolerance, > 0 (integrator 1)",
     1e-6},
    {"absoluteTolerance", "1",
     "CVODE absolute tolerance (m, m/s), > 0 (integrator 1)", 1e-6},
    {"hermiteEnds", "1",
     "1: within a step the ends follow the cubic Hermite curve through the positions "
     "and velocities at both ends; 0: straight lines between the positions",
     1.0},
    {"integrator", "1",
     "0: implicit trapezoidal rule (default); 1: SUNDIALS CVODE (BDF)", 0.0},
    {"maxStep", "s",
     "longest trapezoidal substep, >= 0 (0: one step per coupling step)", 0.0},
    {"freeSurface", "1",
     "1: no buoyancy, drag or added mass above waterLevel (a node's submerged "
     "fraction ramps from 1 to 0 over one segment length around it); 0: the "
     "whole line is submerged",
     0.0},
    {"waterLevel", "m",
     "height (global z) of the still water surface: the free surface "
     "(freeSurface = 1) and the top of the current profile",
     0.0},
    {"seabedFriction", "1",
     "seabed Coulomb friction coefficient (axial and transverse), >= 0 "
     "(0: none)",
     0.0},
    {"frictionVelocity", "m/s",
     "speed below which the seabed friction is regularised (proportional to "
     "the speed), > 0",
     0.01},
    {"endInertia", "1",
     "1: the loads include the inertia of the end nodes' half segments "
     "(mass and added mass times the attachment point's acceleration, "
     "explicit in the coupling); 0 (default): not",
     0.0},
};
constexpr std::size_t scalarCount = sizeof scalars / sizeof scalars[0];

class MooringLineModel final : public fmuExport::LineFmuModel {
public:
    MooringLineModel();

    void checkParameters(const double* values) const override
    {
        connectors::MooringLine law(parameters(values));
    }

    void initializeState(const double* values, double time) override;
    void doStep(double* values, double time, double h) override;
    std::vector<double> internalState() const override;
    void setInternalState(const double* values,
                          const std::vector<double>& state) override;

protected:
    fmuExport::ConnectorOutputs
    evaluate(const double* values, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const override;

private:
    connectors::MooringLineParameters parameters(const double* values) const;
    //- The law for the parameters in `values` (rebuilt when they change)
    connectors::MooringLine& line(const double* values);
    fmuExport::ConnectorOutputs
    lineOutputs(const connectors::MooringLineOutput& out) const;

    //- The flow inputs as points from P to Q; empty when all are zero
    std::vector<connectors::Vector3> flow(const double* values) const;

    Block first_; // first of the scalar parameters, in `scalars` order
    Block currentSurface_, currentSeabed_;
    //- First of the inputs shape.Ux[1..], shape.Uy[1..], shape.Uz[1..]
    fmi2ValueReference flow_ = 0;
    std::unique_ptr<connectors::MooringLine> line_;
    std::vector<double> lineParameters_;
    std::optional<connectors::MooringLineState> state_;
};

MooringLineModel::MooringLineModel()
    : LineFmuModel(
        {"mooringLine",
         "Dynamic lumped-mass mooring line between a body and a seabed "
         "anchor, or between two bodies (integrated inside each step)",
         "1.0.0", lawHtml})
{
    fmuExport::VariableTable& t = table();
    for (const Scalar& s : scalars) {
        const Block b = t.parameter(s.name, Shape::scalar, s.unit,
                                    s.description, {s.start});
        if (&s == scalars) {
            first_ = b;
        }
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
    declareBodies({1, 0, 0});
    std::vector<Block> flowInputs;
    const std::string n = std::to_string(shapePoints);
    for (const char* axis : {"x", "y", "z"}) {
        for (int i = 1; i <= shapePoints; ++i) {
            const std::string point = std::to_string(i);
            const Block b = t.input(
                std::string("shape.U") + axis + "[" + point + "]",
                Shape::scalar, "m/s",
                std::string("water velocity, ") + axis
                    + " (global frame), at point " + point + " of " + n
                    + " of the shape outputs of the previous step, added to "
                      "the current",
                {0.0});
            if (flowInputs.empty()) {
                flow_ = b.first;
            }
            flowInputs.push_back(b);
        }
    }
    const std::vector<Block> positions = positionBlocks();
    const std::vector<Block> motion = join(positions, velocityBlocks());
    const Block all {first_.first, scalarCount};
    OutputDependencies d;
    d.loads = join(join(motion, {all, currentSurface_, currentSeabed_}),
                   flowInputs);
    d.length = positions;
    d.lengthRate = motion;
    d.tension = d.loads;
    d.potentialEnergy = join(positions, {all});
    d.dissipatedPower = d.loads;
    declareLineOutputs(d);
}

connectors::MooringLineParameters
MooringLineModel::parameters(const double* values) const
{
    const double* s = values + first_.first;
    const auto flag = [](const char* name, double value) {
        if (value != 0.0 && value != 1.0) {
            throw connectors::ConnectorError(
                std::string("mooringLine: parameter ") + name + " = "
                + connectors::formatValue(value)
                + " is out of range (allowed: 0 or 1)");
        }
        return value == 1.0;
    };
    const double segments = s[14];
    if (!(segments >= 2.0 && segments <= 1000.0
          && segments == std::floor(segments))) {
        throw connectors::ConnectorError(
            "mooringLine: parameter segments = "
            + connectors::formatValue(segments)
            + " is out of range (allowed: an integer from 2 to 1000)");
    }
    connectors::MooringLineParameters p;
    p.p_AoP_A = vector3(values, A_p);
    p.p_BoQ_B = vector3(values, B_p);
    p.length = s[0];
    p.EA = s[1];
    p.axialDamping = s[2];
    p.massPerLength = s[3];
    p.diameter = s[4];
    p.waterDensity = s[5];
    p.gravity = s[6];
    p.normalDrag = s[7];
    p.tangentialDrag = s[8];
    p.normalAddedMass = s[9];
    p.tangentialAddedMass = s[10];
    p.seabedContact = flag("seabedContact", s[11]);
    p.seabedStiffness = s[12];
    p.seabedDamping = s[13];
    p.segments = int(segments);
    p.relativeTolerance = s[15];
    p.absoluteTolerance = s[16];
    p.hermiteEnds = flag("hermiteEnds", s[17]);
    p.integrator = flag("integrator", s[18])
        ? connectors::MooringLineParameters::Integrator::cvode
        : connectors::MooringLineParameters::Integrator::trapezoid;
    p.maxStep = s[19];
    p.freeSurface = flag("freeSurface", s[20]);
    p.waterLevel = s[21];
    p.seabedFriction = s[22];
    p.frictionVelocity = s[23];
    p.endInertia = flag("endInertia", s[24]);
    p.currentSurface = vector3(values, currentSurface_);
    p.currentSeabed = vector3(values, currentSeabed_);
    return p;
}

std::vector<connectors::Vector3>
MooringLineModel::flow(const double* values) const
{
    std::vector<connectors::Vector3> points(
        static_cast<std::size_t>(shapePoints), connectors::Vector3::Zero());
    bool any = false;
    for (int k = 0; k < shapePoints; ++k) {
        for (int axis = 0; axis < 3; ++axis) {
            const double u = values[flow_ + axis * shapePoints + k];
            points[std::size_t(k)][axis] = u;
            any = any || u != 0.0;
        }
    }
    if (!any) {
        points.clear();
    }
    return points;
}

connectors::MooringLine& MooringLineModel::line(const double* values)
{
    std::vector<double> current(values + first_.first,
                                values + first_.first + scalarCount);
    for (const Block b : {A_p, B_p, currentSurface_, currentSeabed_}) {
        current.insert(current.end(), values + b.first, values + b.first + 3);
    }
    if (!line_ || current != lineParameters_) {
        line_ = std::make_unique<connectors::MooringLine>(parameters(values));
        lineParameters_ = std::move(current);
    }
    return *line_;
}

fmuExport::ConnectorOutputs
MooringLineModel::lineOutputs(const connectors::MooringLineOutput& m) const
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
    return outputs(o);
}

fmuExport::ConnectorOutputs
MooringLineModel::evaluate(const double* values,
                           const connectors::BodyKinematics& A,
                           const connectors::BodyKinematics& B) const
{
    if (state_ && line_) {
        return lineOutputs(
            line_->evaluate(*state_, A, B, shapePoints, flow(values)));
    }
    // Before fmi2ExitInitializationMode: the line at rest in its start shape
    const connectors::MooringLine law(parameters(values));
    return lineOutputs(law.evaluate(law.initialState(A, B, 0.0), A, B,
                                    shapePoints, flow(values)));
}

void MooringLineModel::initializeState(const double* values, double time)
{
    connectors::MooringLine& law = line(values);
    state_ = law.initialState(fmuExport::bodyKinematics(values, A),
                              fmuExport::bodyKinematics(values, B), time);
}

void MooringLineModel::doStep(double* values, double, double h)
{
    if (!state_) {
        throw std::logic_error("mooringLine: fmi2DoStep before the line was "
                               "initialised");
    }
    connectors::MooringLine& law = line(values);
    const connectors::BodyKinematics bodyA
        = fmuExport::bodyKinematics(values, A);
    const connectors::BodyKinematics bodyB
        = fmuExport::bodyKinematics(values, B);
    const std::vector<connectors::Vector3> water = flow(values);
    connectors::MooringLineState next = *state_;
    law.advance(next, bodyA, bodyB, h, water);
    writeOutputs(
        values,
        lineOutputs(law.evaluate(next, bodyA, bodyB, shapePoints, water)));
    state_ = std::move(next);
}

std::vector<double> MooringLineModel::internalState() const
{
    return state_ ? state_->serialize() : std::vector<double> {};
}

void MooringLineModel::setInternalState(const double* values,
                                        const std::vector<double>& state)
{
    if (state.empty()) {
        state_.reset();
        return;
    }
    connectors::MooringLine& law = line(values);
    state_ = connectors::MooringLineState::deserialize(
        state, law.parameters().segments);
}

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<MooringLineModel>();
}

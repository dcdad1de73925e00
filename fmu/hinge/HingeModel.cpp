// hinge.fmu: connectors::Hinge behind the connector FMU interface. The
// variable table below is the only list of its variables.
//
// The FMU state is the value array of the export layer. The `angle` output
// keeps the angle of the previous evaluation there, and each evaluation
// unwraps the new angle against it, so the angle stays continuous through
// any number of turns and is saved, restored and serialized with the FMU
// state (rollback of repeated steps, restart).
#include <cmath>
#include <stdexcept>

#include "BodyInputs.hpp"
#include "Model.hpp"
#include "ModelDescription.hpp"
#include "hinge/Hinge.hpp"

namespace {

using fmuExport::Block;
using fmuExport::Shape;

const char* const lawHtml = R"(<p>A hinge (revolute joint) between A and B
as a penalty force element. P = hinge point <code>A.p</code> on A,
Q = <code>B.p</code> on B; a<sub>A</sub>, a<sub>B</sub> the unit hinge axes
(<code>A.axis</code>, <code>B.axis</code>, normalised), e<sub>A</sub>,
e<sub>B</sub> the angle reference directions (<code>A.ref</code>,
<code>B.ref</code>, made perpendicular to the axis; zero: derived), all in the
global frame; w = &omega;<sub>B</sub> - &omega;<sub>A</sub>:</p>
<pre>
A.F = stiffness (Q - P) + damping v_M,  B.F = -A.F, both at M = (P + Q)/2
   v_M = velocity of B's material point at M minus that of A's
misalignment theta = angle between a_A and a_B                   [rad]
moment on B = rotationalStiffness theta n - rotationalDamping w_perp - ptoTorque a_A
   n = unit(a_B x a_A) (e_A when the axes are opposite),  moment on A = -that
angle = angle from e_A to e_B about a_A, unwrapped                [rad]
angleRate = w . a_A,  w_perp = w - angleRate a_A                  [rad/s]
ptoTorque = ptoStiffness (angle - ptoRestAngle) + ptoDamping angleRate   [N.m]
ptoPower = ptoTorque angleRate (absorbed from the bodies)         [W]
</pre>
<p>Static constraint errors: gap = load / stiffness, misalignment =
moment / rotationalStiffness. Dynamically the penalty adds modes of
frequency omega = sqrt(k / m_eff); loads applied explicitly (OpenFOAM's
rigid-body solvers) are stable for omega dt &lt; 2 (k dt^2 / m_eff &lt; 4).
The angle is unwrapped against its value at the
previous evaluation (kept in the FMU state): between two evaluations the
relative rotation about the axis must stay below pi. Stiffnesses and dampings
must be finite and &ge; 0, the axes non-zero (checked in
fmi2ExitInitializationMode). See connectors/hinge/README.md for the
stability limit of the penalty in an explicit coupling.</p>)";

std::vector<Block> join(std::vector<Block> a, const std::vector<Block>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

class HingeModel final : public fmuExport::Model {
public:
    HingeModel();

    void checkParameters(const double* values) const override
    {
        connectors::Hinge law(parameters(values));
    }

    void computeOutputs(double* values) const override;

private:
    connectors::HingeParameters parameters(const double* values) const;
    void declareOutputs();

    static connectors::Vector3 vector3(const double* values, Block block)
    {
        return fmuExport::blockVector3(values, block);
    }

    Block A_p_, B_p_, A_axis_, B_axis_, A_ref_, B_ref_;
    Block stiffness_, damping_, rotationalStiffness_, rotationalDamping_;
    Block ptoStiffness_, ptoDamping_, ptoRestAngle_;
    fmuExport::BodyInputs A_, B_;
    //- First output and the `angle` output (the unwrapping state)
    Block firstOutput_, angle_;
};

HingeModel::HingeModel()
    : Model({"hinge",
             "Hinge (revolute joint) between two bodies as a penalty force "
             "element, with a rotary power take-off about its axis",
             "1.0.0", lawHtml})
{
    fmuExport::VariableTable& t = table();
    A_p_ = t.parameter("A.p", Shape::vector3, "m",
                       "hinge point on A, A's frame, from A's reference point",
                       {0, 0, 0});
    B_p_ = t.parameter("B.p", Shape::vector3, "m",
                       "hinge point on B, B's frame, from B's reference point "
                       "(a global point when B is the world)",
                       {0, 0, 0});
    A_axis_ = t.parameter("A.axis", Shape::vector3, "1",
                          "hinge axis in A's frame, non-zero (normalised)",
                          {0, 0, 1});
    B_axis_ = t.parameter("B.axis", Shape::vector3, "1",
                          "hinge axis in B's frame, non-zero (normalised)",
                          {0, 0, 1});
    A_ref_ = t.parameter("A.ref", Shape::vector3, "1",
                         "angle reference direction in A's frame, off the "
                         "axis; (0,0,0): the frame axis least aligned with "
                         "A.axis",
                         {0, 0, 0});
    B_ref_ = t.parameter("B.ref", Shape::vector3, "1",
                         "angle reference direction in B's frame, off the "
                         "axis; (0,0,0): the frame axis least aligned with "
                         "B.axis",
                         {0, 0, 0});
    stiffness_ = t.parameter("stiffness", Shape::scalar, "N/m",
                             "translational penalty stiffness, >= 0", {1e5});
    damping_ = t.parameter("damping", Shape::scalar, "N.s/m",
                           "translational penalty damping, >= 0", {100.0});
    rotationalStiffness_
        = t.parameter("rotationalStiffness", Shape::scalar, "N.m/rad",
                      "axis alignment penalty stiffness, >= 0", {1e3});
    rotationalDamping_
        = t.parameter("rotationalDamping", Shape::scalar, "N.m.s/rad",
                      "axis alignment penalty damping, >= 0", {1.0});
    ptoStiffness_
        = t.parameter("ptoStiffness", Shape::scalar, "N.m/rad",
                      "PTO rotary stiffness about the axis, >= 0", {0.0});
    ptoDamping_ = t.parameter("ptoDamping", Shape::scalar, "N.m.s/rad",
                              "PTO rotary damping about the axis, >= 0", {0.0});
    ptoRestAngle_
        = t.parameter("ptoRestAngle", Shape::scalar, "rad",
                      "angle at which the PTO spring is unloaded", {0.0});
    A_ = fmuExport::declareBodyInputs(t, "A", {0, 0, 0});
    B_ = fmuExport::declareBodyInputs(t, "B", {0, 0, 0});
    // Both bodies at the origin with the default hinge points: no load
    t.booleanConstant("inputsStartAtRest",
                      "the start values of inputs and parameters are a "
                      "configuration where the connector exerts no load",
                      true);
    declareOutputs();
}

void HingeModel::declareOutputs()
{
    fmuExport::VariableTable& t = table();
    const std::vector<Block> points = {A_p_, B_p_, A_.r, A_.R, B_.r, B_.R};
    const std::vector<Block> pointMotion
        = join(points, {A_.v, A_.omega, B_.v, B_.omega});
    const std::vector<Block> orientations = {A_.R, B_.R, A_axis_, B_axis_};
    const std::vector<Block> angle = join(orientations, {A_ref_, B_ref_});
    const std::vector<Block> angleRate = {A_.R, A_axis_, A_.omega, B_.omega};
    const std::vector<Block> pto = join(
        join(angle, angleRate), {ptoStiffness_, ptoDamping_, ptoRestAngle_});
    const std::vector<Block> loads = join(
        join(pointMotion, pto),
        {stiffness_, damping_, rotationalStiffness_, rotationalDamping_});
    const std::vector<Block> energy = join(
        join(points, angle),
        {stiffness_, rotationalStiffness_, ptoStiffness_, ptoRestAngle_});
    const std::vector<Block> dissipation
        = join(join(pointMotion, angleRate),
               {damping_, rotationalDamping_, ptoDamping_});

    firstOutput_ = t.output("A.F", Shape::vector3, "N",
                            "force of the hinge on A, global frame", loads);
    t.output("A.M", Shape::vector3, "N.m",
             "moment of the hinge on A about A's reference point, global frame",
             loads);
    t.output("B.F", Shape::vector3, "N",
             "force of the hinge on B, global frame", loads);
    t.output("B.M", Shape::vector3, "N.m",
             "moment of the hinge on B about B's reference point, global frame",
             loads);
    t.output("length", Shape::scalar, "m",
             "distance between the hinge points (the same as gap)", points);
    t.output("lengthRate", Shape::scalar, "m/s",
             "time derivative of the length", pointMotion);
    t.output("tension", Shape::scalar, "N",
             "penalty force along P->Q, positive when it pulls the hinge "
             "points together",
             join(pointMotion, {stiffness_, damping_}));
    t.output("potentialEnergy", Shape::scalar, "J",
             "energy stored in the penalty springs and the PTO spring", energy);
    t.output("dissipatedPower", Shape::scalar, "W",
             "power dissipated by the penalty and PTO dampers, never negative",
             dissipation);
    angle_ = t.output("angle", Shape::scalar, "rad",
                      "relative angle of B about the hinge axis from A.ref to "
                      "B.ref, continuous through full turns",
                      angle);
    t.output("angleRate", Shape::scalar, "rad/s",
             "relative angular velocity about A's hinge axis", angleRate);
    t.output("gap", Shape::scalar, "m",
             "distance between the hinge points (constraint error)", points);
    t.output("misalignment", Shape::scalar, "rad",
             "angle between the two hinge axes (constraint error), 0 to pi",
             orientations);
    t.output("ptoTorque", Shape::scalar, "N.m",
             "PTO torque about the axis, positive when it resists a positive "
             "angle",
             pto);
    t.output("ptoPower", Shape::scalar, "W",
             "power absorbed by the PTO from the bodies", pto);
}

connectors::HingeParameters HingeModel::parameters(const double* values) const
{
    connectors::HingeParameters p;
    p.p_AoP_A = vector3(values, A_p_);
    p.p_BoQ_B = vector3(values, B_p_);
    p.axis_A = vector3(values, A_axis_);
    p.axis_B = vector3(values, B_axis_);
    p.ref_A = vector3(values, A_ref_);
    p.ref_B = vector3(values, B_ref_);
    p.stiffness = values[stiffness_.first];
    p.damping = values[damping_.first];
    p.rotationalStiffness = values[rotationalStiffness_.first];
    p.rotationalDamping = values[rotationalDamping_.first];
    p.ptoStiffness = values[ptoStiffness_.first];
    p.ptoDamping = values[ptoDamping_.first];
    p.ptoRestAngle = values[ptoRestAngle_.first];
    return p;
}

void HingeModel::computeOutputs(double* values) const
{
    const connectors::Hinge law(parameters(values));
    const connectors::HingeResult h = law.evaluate(
        fmuExport::bodyKinematics(values, A_),
        fmuExport::bodyKinematics(values, B_), values[angle_.first]);
    const connectors::ConnectorResult& r = h.loads;
    const double out[]
        = {r.A.f_W[0],        r.A.f_W[1],    r.A.f_W[2],    r.A.m_Bo_W[0],
           r.A.m_Bo_W[1],     r.A.m_Bo_W[2], r.B.f_W[0],    r.B.f_W[1],
           r.B.f_W[2],        r.B.m_Bo_W[0], r.B.m_Bo_W[1], r.B.m_Bo_W[2],
           r.length,          r.lengthRate,  r.tension,     r.potentialEnergy,
           r.dissipatedPower, h.angle,       h.angleRate,   h.gap,
           h.misalignment,    h.ptoTorque,   h.ptoPower};
    const std::size_t n = sizeof out / sizeof out[0];
    const std::vector<fmuExport::ScalarVariable>& variables
        = this->variables().variables();
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(out[i])) {
            throw std::range_error(
                "hinge: output " + variables[firstOutput_.first + i].name
                + " = " + fmuExport::formatDouble(out[i])
                + " is not finite (inputs or parameters too large)");
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        values[firstOutput_.first + i] = out[i];
    }
}

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<HingeModel>();
}

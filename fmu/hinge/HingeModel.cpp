// hinge.fmu: connectors::Hinge behind the connector FMU interface. The
// variable table below is the only list of its variables.
//
// The FMU state is the value array of the export layer. The `angle` output
// keeps the angle of the previous evaluation there, and each evaluation
// unwraps the new angle against it, so the angle stays continuous through
// any number of turns and is saved, restored and serialized with the FMU
// state (rollback of repeated steps, restart).
#include "LawFmuModel.hpp"
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

fmuExport::ConnectorWording hingeWording()
{
    fmuExport::ConnectorWording w;
    w.noun = "hinge";
    w.A_p = "hinge point on A";
    w.B_p = "hinge point on B";
    w.length = "distance between the hinge points (the same as gap)";
    w.tension = "penalty force along P->Q, positive when it pulls the hinge "
                "points together";
    w.potentialEnergy
        = "energy stored in the penalty springs and the PTO spring";
    w.dissipatedPower
        = "power dissipated by the penalty and PTO dampers, never negative";
    return w;
}

using Parameters = connectors::HingeParameters;

class HingeModel final
    : public fmuExport::LawFmuModel<connectors::Hinge, Parameters> {
public:
    HingeModel();

protected:
    fmuExport::ConnectorOutputs
    evaluate(const double* values, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const override;

private:
    void declareHingeOutputs();

    Block A_axis_, B_axis_, A_ref_, B_ref_;
    Block stiffness_, damping_, rotationalStiffness_, rotationalDamping_;
    Block ptoStiffness_, ptoDamping_, ptoRestAngle_;
    //- The `angle` output (the unwrapping state)
    Block angle_;
};

HingeModel::HingeModel()
    : LawFmuModel({"hinge",
                   "Hinge (revolute joint) between two bodies as a "
                   "penalty force element, with a rotary power take-off "
                   "about its axis",
                   "1.0.0", lawHtml},
                  hingeWording())
{
    A_axis_ = parameter(&Parameters::axis_A, "A.axis", "1",
                        "hinge axis in A's frame, non-zero (normalised)",
                        {0, 0, 1});
    B_axis_ = parameter(&Parameters::axis_B, "B.axis", "1",
                        "hinge axis in B's frame, non-zero (normalised)",
                        {0, 0, 1});
    A_ref_ = parameter(&Parameters::ref_A, "A.ref", "1",
                       "angle reference direction in A's frame, off the "
                       "axis; (0,0,0): the frame axis least aligned with "
                       "A.axis",
                       {0, 0, 0});
    B_ref_ = parameter(&Parameters::ref_B, "B.ref", "1",
                       "angle reference direction in B's frame, off the "
                       "axis; (0,0,0): the frame axis least aligned with "
                       "B.axis",
                       {0, 0, 0});
    stiffness_ = parameter(&Parameters::stiffness, "stiffness", "N/m",
                           "translational penalty stiffness, >= 0", 1e5);
    damping_ = parameter(&Parameters::damping, "damping", "N.s/m",
                         "translational penalty damping, >= 0", 100.0);
    rotationalStiffness_
        = parameter(&Parameters::rotationalStiffness, "rotationalStiffness",
                    "N.m/rad", "axis alignment penalty stiffness, >= 0", 1e3);
    rotationalDamping_
        = parameter(&Parameters::rotationalDamping, "rotationalDamping",
                    "N.m.s/rad", "axis alignment penalty damping, >= 0", 1.0);
    ptoStiffness_
        = parameter(&Parameters::ptoStiffness, "ptoStiffness", "N.m/rad",
                    "PTO rotary stiffness about the axis, >= 0", 0.0);
    ptoDamping_ = parameter(&Parameters::ptoDamping, "ptoDamping", "N.m.s/rad",
                            "PTO rotary damping about the axis, >= 0", 0.0);
    ptoRestAngle_ = parameter(&Parameters::ptoRestAngle, "ptoRestAngle", "rad",
                              "angle at which the PTO spring is unloaded", 0.0);
    // Both bodies at the origin with the default hinge points: no load
    declareBodies({0, 0, 0});
    declareStartAtRest();
    declareHingeOutputs();
}

void HingeModel::declareHingeOutputs()
{
    const std::vector<Block> points = positionBlocks();
    const std::vector<Block> pointMotion = join(points, velocityBlocks());
    const std::vector<Block> orientations = {A.R, B.R, A_axis_, B_axis_};
    const std::vector<Block> angle = join(orientations, {A_ref_, B_ref_});
    const std::vector<Block> angleRate = {A.R, A_axis_, A.omega, B.omega};
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

    OutputDependencies d;
    d.loads = loads;
    d.length = points;
    d.lengthRate = pointMotion;
    d.tension = join(pointMotion, {stiffness_, damping_});
    d.potentialEnergy = energy;
    d.dissipatedPower = dissipation;
    declareOutputs(d);
    angle_
        = extraOutput("angle", Shape::scalar, "rad",
                      "relative angle of B about the hinge axis from A.ref to "
                      "B.ref, continuous through full turns",
                      angle);
    extraOutput("angleRate", Shape::scalar, "rad/s",
                "relative angular velocity about A's hinge axis", angleRate);
    extraOutput("gap", Shape::scalar, "m",
                "distance between the hinge points (constraint error)", points);
    extraOutput("misalignment", Shape::scalar, "rad",
                "angle between the two hinge axes (constraint error), 0 to pi",
                orientations);
    extraOutput(
        "ptoTorque", Shape::scalar, "N.m",
        "PTO torque about the axis, positive when it resists a positive "
        "angle",
        pto);
    extraOutput("ptoPower", Shape::scalar, "W",
                "power absorbed by the PTO from the bodies", pto);
}

fmuExport::ConnectorOutputs
HingeModel::evaluate(const double* values, const connectors::BodyKinematics& A,
                     const connectors::BodyKinematics& B) const
{
    const connectors::HingeResult h
        = law().evaluate(A, B, scalar(values, angle_));
    return {
        h.loads,
        {h.angle, h.angleRate, h.gap, h.misalignment, h.ptoTorque, h.ptoPower}};
}

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<HingeModel>();
}

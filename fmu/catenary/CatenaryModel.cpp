// catenary.fmu: connectors::Catenary behind the connector FMU interface. The
// variable table below is the only list of its variables.
//
// The FMU state is the value array of the export layer. The H and V outputs
// keep the solution of the previous evaluation there; each evaluation warm
// starts Newton from them, so a restored state repeats a step exactly.
#include "LineFmuModel.hpp"
#include "catenary/Catenary.hpp"
#include "common/ConnectorError.hpp"

namespace {

using fmuExport::Block;
using fmuExport::Shape;

const char* const lawHtml = R"(<p>A quasi-static elastic catenary mooring
line of unstretched length L (<code>unstretchedLength</code>), axial
stiffness <code>EA</code> and submerged weight per unstretched length w
(<code>weight</code>; negative: buoyant) between the fairlead P
(<code>A.p</code> on A) and Q (<code>B.p</code> on B): an anchor on the
seabed (<code>seabedContact</code> = 1, the seabed is the horizontal plane
through Q, Coulomb friction <code>seabedFriction</code>) or a fairlead on a
second body (<code>seabedContact</code> = 0, no seabed). With x, z the
horizontal and vertical spans from Q to P, H the horizontal and V the
vertical tension at P, a = V/H, b = (V - wL)/H:</p>
<pre>
suspended:  x = (H/w)(asinh a - asinh b) + H L/EA
            z = (H/w)(sqrt(1+a^2) - sqrt(1+b^2)) + (V L - w L^2/2)/EA
touchdown:  x = Lb + (H/w) asinh a + H L/EA + friction term,  Lb = L - V/w
            z = (H/w)(sqrt(1+a^2) - 1) + V^2/(2 EA w)
A.F = -H e_h - V e_z (at P),  B.F = HA e_h + VA e_z (at Q)
</pre>
<p>e_h is the horizontal unit vector from Q towards P. H and V are found by
a damped Newton method warm started from the previous step (outputs
<code>H</code>, <code>V</code>, part of the FMU state). Slack lines on the
seabed, vertical (taut or folded) lines and slack weightless lines are
solved in closed form. fmi2Error (with the regime and residual in the
message) for a fairlead below the seabed and a Newton failure.
No SUNDIALS dependency. Details: connectors/catenary/README.md.</p>)";

class CatenaryModel final : public fmuExport::LineFmuModel {
public:
    CatenaryModel();

    void setParameters(const double* values) override
    {
        law_.build(parameters(values));
    }

protected:
    fmuExport::ConnectorOutputs
    evaluate(const double* values, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const override;

private:
    connectors::CatenaryParameters parameters(const double* values) const;

    Block length_, EA_, weight_, seabedContact_, seabedFriction_;
    fmuExport::BuiltLaw<connectors::Catenary> law_;
};

CatenaryModel::CatenaryModel()
    : LineFmuModel(
        {"catenary",
         "Quasi-static elastic catenary mooring line between a body and "
         "a seabed anchor, or between two bodies",
         "1.0.0", lawHtml})
{
    fmuExport::VariableTable& t = table();
    length_ = t.parameter("unstretchedLength", Shape::scalar, "m",
                          "unstretched length L of the line, > 0", {1.5});
    EA_ = t.parameter("EA", Shape::scalar, "N", "axial stiffness EA, > 0",
                      {1e5});
    weight_ = t.parameter("weight", Shape::scalar, "N/m",
                          "submerged weight per unstretched length (negative: "
                          "buoyant line)",
                          {1.0});
    seabedContact_ = t.parameter("seabedContact", Shape::scalar, "1",
                                 "1: B.p is an anchor on the seabed (the "
                                 "horizontal plane through it); 0: no seabed",
                                 {0.0});
    seabedFriction_ = t.parameter("seabedFriction", Shape::scalar, "1",
                                  "seabed friction coefficient, >= 0", {0.0});
    declareBodies({1, 0, 0});
    const std::vector<Block> positions = positionBlocks();
    OutputDependencies d;
    d.loads = join(positions,
                   {length_, EA_, weight_, seabedContact_, seabedFriction_});
    d.length = positions;
    d.lengthRate = join(positions, velocityBlocks());
    d.tension = d.loads;
    d.potentialEnergy = d.loads;
    declareLineOutputs(d);
}

connectors::CatenaryParameters
CatenaryModel::parameters(const double* values) const
{
    connectors::CatenaryParameters p;
    p.p_AoP_A = vector3(values, A_p);
    p.p_BoQ_B = vector3(values, B_p);
    p.line.length = scalar(values, length_);
    p.line.EA = scalar(values, EA_);
    p.line.weight = scalar(values, weight_);
    p.line.seabedContact = flag(values, seabedContact_);
    p.line.seabedFriction = scalar(values, seabedFriction_);
    return p;
}

fmuExport::ConnectorOutputs
CatenaryModel::evaluate(const double* values,
                        const connectors::BodyKinematics& A,
                        const connectors::BodyKinematics& B) const
{
    const connectors::CatenaryGuess previous {scalar(values, H),
                                              scalar(values, V)};
    const connectors::CatenaryOutput c
        = law_.get().evaluate(A, B, &previous, shapePoints);
    fmuExport::LineOutputs o;
    o.loads = c.loads;
    o.fairleadTension = c.fairleadTension;
    o.anchorTension = c.anchorTension;
    o.groundedLength = c.solution.groundedLength;
    o.H = c.solution.H;
    o.V = c.solution.V;
    o.shape = c.shape;
    o.tension = c.shapeTension;
    return outputs(o);
}

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<CatenaryModel>();
}

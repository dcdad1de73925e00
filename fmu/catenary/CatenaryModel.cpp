// catenary.fmu: connectors::Catenary behind the connector FMU interface. The
// variable table below is the only list of its variables.
//
// The FMU state is the value array of the export layer. The H and V outputs
// keep the solution of the previous evaluation there; each evaluation warm
// starts Newton from them, so a restored state repeats a step exactly.
#include <cmath>
#include <string>

#include "LineFmuModel.hpp"
#include "LineSections.hpp"
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
No SUNDIALS dependency. Details: connectors/catenary/README.md.</p>
<p>Sections: the line may be made of up to 4 sections from B.p towards
A.p, as in mooringLine.fmu: section 1 is the line above, section k = 2..4
has <code>section&lt;k&gt;.unstretchedLength</code> (0: none),
<code>.EA</code> and <code>.weight</code> (submerged weight per length, as
<code>weight</code>), and the point at its lower joint
<code>joint&lt;k-1&gt;.weight</code>, its net submerged weight in N (a
clump weight: &gt; 0, a buoy: its buoyancy less its weight, &lt; 0). Each
suspended piece is the closed form above with the vertical tension falling
by the sections' and points' weights; the grounded part may reach over
several sections and rest a clump weight on the seabed. fmi2Error, naming
the section or joint, for a buoyant section or a buoy below the touchdown
point or a sag through the seabed (the line would touch it twice), and for
a folded line of sections.</p>
<p>Local variables (read when asked for, not outputs):
<code>shape.section[k]</code>, the section (1 at B.p) that shape point k
lies in; <code>section.lowerTension[k]</code>,
<code>section.upperTension[k]</code> (N), the tension at the ends of
section k towards B.p and towards A.p; <code>joint.x[k]</code>,
<code>.y</code>, <code>.z</code> (m, global frame), the joint of sections
k and k+1; 0 for an absent section or joint.</p>)";

//- Sections of the line, the first (unstretchedLength, EA, weight) included
constexpr int maxSections = 4;

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

    //- The sections after the first into p.line.sections; throws
    //  connectors::ParameterError naming the parameter for a negative
    //  length, a section after a missing one, a joint without a section
    //  above it (the law checks the rest)
    void readSections(const double* values,
                      connectors::CatenaryParameters& p) const;

    Block length_, EA_, weight_, seabedContact_, seabedFriction_;
    //- Per section k = 2..maxSections: joint<k-1>.weight, then
    //  section<k>.unstretchedLength, .EA, .weight; all of them
    std::vector<Block> sections_;
    Block allSections_;
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
    allSections_.first = fmi2ValueReference(t.size());
    for (int k = 2; k <= maxSections; ++k) {
        const std::string n = std::to_string(k), below = std::to_string(k - 1);
        const std::string of = "section " + n + " (from B.p): ";
        const Block joint = t.parameter(
            "joint" + below + ".weight", Shape::scalar, "N",
            "joint " + below + " (of sections " + below + " and " + n
                + " from B.p): net submerged weight of its point (clump "
                  "weight > 0, buoy < 0)",
            {0.0});
        t.parameter("section" + n + ".unstretchedLength", Shape::scalar, "m",
                    of + "unstretched length, >= 0 (0: no such section)",
                    {0.0});
        t.parameter("section" + n + ".EA", Shape::scalar, "N",
                    of + "axial stiffness, > 0", {1e5});
        t.parameter("section" + n + ".weight", Shape::scalar, "N/m",
                    of
                        + "submerged weight per unstretched length (negative: "
                          "buoyant)",
                    {1.0});
        sections_.push_back({joint.first, 4});
    }
    allSections_.size = t.size() - allSections_.first;
    declareBodies({1, 0, 0});
    const std::vector<Block> positions = positionBlocks();
    OutputDependencies d;
    d.loads = join(
        positions,
        {length_, EA_, weight_, seabedContact_, seabedFriction_, allSections_});
    d.length = positions;
    d.lengthRate = join(positions, velocityBlocks());
    d.tension = d.loads;
    d.potentialEnergy = d.loads;
    declareLineOutputs(d);
    // the sections' variables as locals: the outputs stay the uniform
    // line's, which importers record by default
    declareShapeSections();
    for (const fmuExport::lineSections::Variable& v :
         fmuExport::lineSections::endVariables(maxSections, "")) {
        extraLocal(v.name, Shape::scalar, v.unit, v.description);
    }
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
    readSections(values, p);
    return p;
}

void CatenaryModel::readSections(const double* values,
                                 connectors::CatenaryParameters& p) const
{
    const auto refuse = [&](connectors::Refusal code, fmi2ValueReference vr,
                            const char* unit, const std::string& allowed) {
        throw connectors::ParameterError(code, "catenary",
                                         variables().variables()[vr].name,
                                         values[vr], unit, allowed);
    };
    bool ended = false; // a section was missing
    for (std::size_t k = 0; k < sections_.size(); ++k) {
        const fmi2ValueReference joint = sections_[k].first, length = joint + 1;
        const std::string number = std::to_string(k + 2);
        if (!(std::isfinite(values[length]) && values[length] >= 0.0)) {
            refuse(std::isfinite(values[length])
                       ? connectors::Refusal::negative
                       : connectors::Refusal::notFinite,
                   length, "m", "finite and >= 0; 0: no section " + number);
        }
        const bool present = values[length] > 0.0;
        if (present && ended) {
            refuse(connectors::Refusal::inconsistent, length, "m",
                   "0 while an earlier section's unstretchedLength is 0: the "
                   "sections follow each other from B.p, without gaps");
        }
        if (!present && values[joint] != 0.0) {
            refuse(connectors::Refusal::inconsistent, joint, "N",
                   "0 without section " + number
                       + ": a joint lies between two sections");
        }
        ended = ended || !present;
        if (present) {
            connectors::CatenarySection s;
            s.jointWeight = values[joint];
            s.length = values[length];
            s.EA = values[length + 1];
            s.weight = values[length + 2];
            p.line.sections.push_back(s);
        }
    }
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
    const connectors::CatenaryLine& line = law_.get().parameters().line;
    o.sectionLengths = {line.length};
    for (const connectors::CatenarySection& s : line.sections) {
        o.sectionLengths.push_back(s.length);
    }
    fmuExport::ConnectorOutputs all = outputs(o);
    const std::vector<double> ends = fmuExport::lineSections::endValues(
        maxSections, c.sectionLowerTension, c.sectionUpperTension, c.joints);
    all.locals.insert(all.locals.end(), ends.begin(), ends.end());
    return all;
}

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<CatenaryModel>();
}

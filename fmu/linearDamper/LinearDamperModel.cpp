// linearDamper.fmu: connectors::LinearDamper behind the connector FMU
// interface. The variable table below is the only list of its variables.
#include "ConnectorFmuModel.hpp"
#include "linearDamper/LinearDamper.hpp"

namespace {

using fmuExport::Block;
using fmuExport::Shape;

const char* const lawHtml = R"(<p>A linear damper along the line from P
(attachment point <code>A.p</code> on A) to Q (<code>B.p</code> on B). With
e = (Q - P)/|Q - P| and v<sub>rel</sub> = v<sub>Q</sub> - v<sub>P</sub>:</p>
<pre>
lengthRate = e . v_rel                                      [m/s]
B.F = -damping (v_rel . e) e (at Q),   A.F = -B.F (at P)    [N]
A.M = (A.R A.p) x A.F,   B.M = (B.R B.p) x B.F              [N.m]
tension = damping lengthRate                                [N]
potentialEnergy = 0,  dissipatedPower = damping lengthRate^2 [W]
</pre>
<p>Below a length of 1e-12 m the axis is undefined and the force is zero.
damping must be finite and &ge; 0 (checked in
fmi2ExitInitializationMode).</p>)";

class LinearDamperModel final : public fmuExport::ConnectorFmuModel {
public:
    LinearDamperModel()
        : ConnectorFmuModel({"linearDamper",
                             "Linear damper along the line between two "
                             "attachment points",
                             "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        damping_ = table().parameter("damping", Shape::scalar, "N.s/m",
                                     "damping coefficient c, >= 0", {100.0});
        const std::vector<Block> positions = positionBlocks();
        const std::vector<Block> motion = join(positions, velocityBlocks());
        OutputDependencies d;
        d.loads = join(motion, {damping_});
        d.length = positions;
        d.lengthRate = motion;
        d.tension = d.loads;
        d.potentialEnergy = {};
        d.dissipatedPower = d.loads;
        declareOutputs(d);
        declareStartAtRest();
    }

    void setParameters(const double* values) override
    {
        law_.build(parameters(values));
    }

protected:
    fmuExport::ConnectorOutputs
    evaluate(const double*, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const override
    {
        return law_.get().evaluate(A, B);
    }

private:
    connectors::LinearDamperParameters parameters(const double* values) const
    {
        connectors::LinearDamperParameters p;
        p.p_AoP_A = vector3(values, A_p);
        p.p_BoQ_B = vector3(values, B_p);
        p.damping = scalar(values, damping_);
        return p;
    }

    Block damping_;
    fmuExport::BuiltLaw<connectors::LinearDamper> law_;
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<LinearDamperModel>();
}

// linearSpring.fmu: connectors::LinearSpring behind the connector FMU
// interface. The variable table below is the only list of its variables.
#include "ConnectorFmuModel.hpp"
#include "linearSpring/LinearSpring.hpp"

namespace {

using fmuExport::Block;
using fmuExport::Shape;

const char* const lawHtml = R"(<p>A linear spring with optional damping along
its axis between P (attachment point <code>A.p</code> on A) and Q
(<code>B.p</code> on B). With L = |Q - P|, e = (Q - P)/L and
dL/dt = e &middot; (v<sub>Q</sub> - v<sub>P</sub>):</p>
<pre>
tension T = stiffness (L - restLength) + damping dL/dt      [N]
A.F = +T e (at P),   B.F = -T e (at Q)                      [N]
A.M = (A.R A.p) x A.F,   B.M = (B.R B.p) x B.F              [N.m]
potentialEnergy = stiffness (L - restLength)^2 / 2          [J]
dissipatedPower = damping (dL/dt)^2                         [W]
</pre>
<p>Below a length of 1e-12 m the direction e is undefined: with
restLength = 0 the elastic force is the vector stiffness (Q - P), with
restLength &gt; 0 and stiffness &gt; 0 the FMU returns fmi2Error; the damping
force is zero there. stiffness, restLength and damping must be finite and
&ge; 0 (checked in fmi2ExitInitializationMode).</p>)";

class LinearSpringModel final : public fmuExport::ConnectorFmuModel {
public:
    LinearSpringModel()
        : ConnectorFmuModel(
            {"linearSpring",
             "Linear spring with optional axial damping between "
             "two bodies",
             "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        stiffness_ = table().parameter("stiffness", Shape::scalar, "N/m",
                                       "spring stiffness k, >= 0", {1000.0});
        restLength_ = table().parameter("restLength", Shape::scalar, "m",
                                        "rest length L0, >= 0", {1.0});
        damping_
            = table().parameter("damping", Shape::scalar, "N.s/m",
                                "axial damping coefficient c, >= 0", {0.0});
        const std::vector<Block> positions = positionBlocks();
        const std::vector<Block> motion = join(positions, velocityBlocks());
        OutputDependencies d;
        d.loads = join(motion, {stiffness_, restLength_, damping_});
        d.length = positions;
        d.lengthRate = motion;
        d.tension = d.loads;
        d.potentialEnergy = join(positions, {stiffness_, restLength_});
        d.dissipatedPower = join(motion, {damping_});
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
    connectors::LinearSpringParameters parameters(const double* values) const
    {
        connectors::LinearSpringParameters p;
        p.p_AoP_A = vector3(values, A_p);
        p.p_BoQ_B = vector3(values, B_p);
        p.stiffness = scalar(values, stiffness_);
        p.restLength = scalar(values, restLength_);
        p.damping = scalar(values, damping_);
        return p;
    }

    Block stiffness_, restLength_, damping_;
    fmuExport::BuiltLaw<connectors::LinearSpring> law_;
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<LinearSpringModel>();
}

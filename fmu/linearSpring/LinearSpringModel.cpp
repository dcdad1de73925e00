// linearSpring.fmu: connectors::LinearSpring behind the connector FMU
// interface. The variable table below is the only list of its variables.
#include "LawFmuModel.hpp"
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

using Parameters = connectors::LinearSpringParameters;

class LinearSpringModel final
    : public fmuExport::LawFmuModel<connectors::LinearSpring, Parameters> {
public:
    LinearSpringModel()
        : LawFmuModel({"linearSpring",
                       "Linear spring with optional axial damping between "
                       "two bodies",
                       "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        stiffness_ = parameter(&Parameters::stiffness, "stiffness", "N/m",
                               "spring stiffness k, >= 0", 1000.0);
        restLength_ = parameter(&Parameters::restLength, "restLength", "m",
                                "rest length L0, >= 0", 1.0);
        damping_ = parameter(&Parameters::damping, "damping", "N.s/m",
                             "axial damping coefficient c, >= 0", 0.0);
        OutputDependencies d
            = pointToPointDependencies({stiffness_, restLength_, damping_});
        d.potentialEnergy = join(positionBlocks(), {stiffness_, restLength_});
        d.dissipatedPower = join(d.lengthRate, {damping_});
        declareOutputs(d);
        declareStartAtRest();
    }

private:
    Block stiffness_, restLength_, damping_;
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<LinearSpringModel>();
}

// linearDamper.fmu: connectors::LinearDamper behind the connector FMU
// interface. The variable table below is the only list of its variables.
#include "LawFmuModel.hpp"
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

class LinearDamperModel final
    : public fmuExport::LawFmuModel<connectors::LinearDamper,
                                    connectors::LinearDamperParameters> {
public:
    LinearDamperModel()
        : LawFmuModel({"linearDamper",
                       "Linear damper along the line between two "
                       "attachment points",
                       "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        damping_
            = parameter(&connectors::LinearDamperParameters::damping, "damping",
                        "N.s/m", "damping coefficient c, >= 0", 100.0);
        declareOutputs(pointToPointDependencies({damping_}));
        declareStartAtRest();
    }

private:
    Block damping_;
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<LinearDamperModel>();
}

// rotationalDamper.fmu: connectors::RotationalDamper behind the connector
// FMU interface. The variable table below is the only list of its
// variables.
#include "LawFmuModel.hpp"
#include "rotationalDamper/RotationalDamper.hpp"

namespace {

using fmuExport::Block;

const char* const lawHtml = R"(<p>A linear viscous damper on the angular
velocity of B relative to A, about every axis: equal and opposite couples.
With w<sub>rel</sub> = B.omega - A.omega:</p>
<pre>
A.M = damping w_rel,   B.M = -A.M   (couples)              [N.m]
A.F = B.F = 0                                              [N]
length = |Q - P| (A.p, B.p), lengthRate = e . (v_Q - v_P)  [m, m/s]
tension = 0,  potentialEnergy = 0
dissipatedPower = damping |w_rel|^2                        [W]
</pre>
<p>A.p and B.p give only length and lengthRate. OpenFOAM's built-in
sphericalAngularDamper restraint is this damper with B the fixed world.
damping must be finite and &ge; 0 (checked in
fmi2ExitInitializationMode).</p>)";

class RotationalDamperModel final
    : public fmuExport::LawFmuModel<connectors::RotationalDamper,
                                    connectors::RotationalDamperParameters> {
public:
    RotationalDamperModel()
        : LawFmuModel({"rotationalDamper",
                       "Linear viscous damper on the relative angular "
                       "velocity of two bodies, about every axis",
                       "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        damping_ = parameter(&connectors::RotationalDamperParameters::damping,
                             "damping", "N.m.s/rad",
                             "damping coefficient c, >= 0", 10.0);
        declareOutputs(pointToPointDependencies({damping_}));
        declareStartAtRest();
    }

private:
    Block damping_;
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<RotationalDamperModel>();
}

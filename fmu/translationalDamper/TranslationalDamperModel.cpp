// translationalDamper.fmu: connectors::TranslationalDamper behind the
// connector FMU interface. The variable table below is the only list of its
// variables.
#include "LawFmuModel.hpp"
#include "translationalDamper/TranslationalDamper.hpp"

namespace {

using fmuExport::Block;

const char* const lawHtml = R"(<p>A linear viscous damper at the point P
(<code>A.p</code> on A) on the velocity of B's material point at P
relative to A's, in every direction. With P = A.r + A.R A.p,
v<sub>rel</sub> = (B.v + B.omega x (P - B.r)) - (A.v + A.omega x (A.R A.p)),
Q = B.r + B.R B.p and e = (Q - P)/|Q - P|:</p>
<pre>
A.F = damping v_rel (at P),   B.F = -A.F (at P)             [N]
A.M = (A.R A.p) x A.F,   B.M = (P - B.r) x B.F              [N.m]
length = |Q - P|,  lengthRate = e . (v_Q - v_P)             [m, m/s]
tension = A.F . e                                           [N]
potentialEnergy = 0,  dissipatedPower = damping |v_rel|^2   [W]
</pre>
<p>B.p gives only length, lengthRate and tension. OpenFOAM's built-in
linearDamper restraint is this damper with A.p = 0 and B the fixed world.
Below a length of 1e-12 m lengthRate and tension are 0. damping must be
finite and &ge; 0 (checked in fmi2ExitInitializationMode).</p>)";

class TranslationalDamperModel final
    : public fmuExport::LawFmuModel<connectors::TranslationalDamper,
                                    connectors::TranslationalDamperParameters> {
public:
    TranslationalDamperModel()
        : LawFmuModel({"translationalDamper",
                       "Linear viscous damper on the relative velocity of "
                       "two attachment points, in every direction",
                       "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        damping_ = parameter(
            &connectors::TranslationalDamperParameters::damping, "damping",
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
    return std::make_unique<TranslationalDamperModel>();
}

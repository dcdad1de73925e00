// axialAngularSpring.fmu: connectors::AxialAngularSpring behind the
// connector FMU interface. The variable table below is the only list of its
// variables.
#include "LawFmuModel.hpp"
#include "axialAngularSpring/AxialAngularSpring.hpp"

namespace {

using fmuExport::Block;
using Parameters = connectors::AxialAngularSpringParameters;

const char* const lawHtml = R"(<p>OpenFOAM's sixDoF linearAxialAngularSpring
restraint between A and B: a moment about the axis <code>B.axis</code>
(fixed in B) that turns A back towards its reference orientation
<code>referenceOrientation</code> relative to B. In B's frame, with n the
unit axis and R = B.R<sup>T</sup> A.R:</p>
<pre>
d = T e_y, T = rotationTensor(e_x, n)  (d = T e_z where Q0 d or R d
    comes within 0.95 of n)
u = Q0 d, w = R d, each less its part along n, normalised
theta = |acos(u . w)|,  a = n sign((u x w) . n)
A.M = B.R (-(stiffness theta + damping (w_rel . a)) a),  B.M = -A.M
w_rel = B.R^T (A.omega - B.omega);  A.F = B.F = 0
potentialEnergy = stiffness theta^2 / 2,  dissipatedPower = damping (w_rel . a)^2
</pre>
<p>To the fixed world it is OpenFOAM's restraint with axis = B.axis and
referenceOrientation. stiffness and damping must be finite and &ge; 0,
B.axis finite and not zero, referenceOrientation a rotation tensor as
OpenFOAM checks it (checked in fmi2ExitInitializationMode).</p>)";

class AxialAngularSpringModel final
    : public fmuExport::LawFmuModel<connectors::AxialAngularSpring,
                                    Parameters> {
public:
    AxialAngularSpringModel()
        : LawFmuModel({"axialAngularSpring",
                       "OpenFOAM's linearAxialAngularSpring: a moment about an "
                       "axis fixed in B towards a reference orientation",
                       "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        const Block axis
            = parameter(&Parameters::axis_B, "B.axis", "1",
                        "the axis n, B's frame (normalised)", {0, 0, 1});
        const Block reference = referenceOrientation();
        const Block stiffness = parameter(&Parameters::stiffness, "stiffness",
                                          "N.m/rad", "stiffness k, >= 0", 10.0);
        const Block damping = parameter(&Parameters::damping, "damping",
                                        "N.m.s/rad", "damping c, >= 0", 0.0);
        OutputDependencies d
            = pointToPointDependencies({axis, reference, stiffness, damping});
        d.tension = {};
        d.potentialEnergy
            = join(positionBlocks(), {axis, reference, stiffness});
        declareOutputs(d);
        declareStartAtRest();
    }
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<AxialAngularSpringModel>();
}

// sphericalAngularSpring.fmu: connectors::SphericalAngularSpring behind the
// connector FMU interface. The variable table below is the only list of its
// variables.
#include "LawFmuModel.hpp"
#include "sphericalAngularSpring/SphericalAngularSpring.hpp"

namespace {

using fmuExport::Block;
using Parameters = connectors::SphericalAngularSpringParameters;

const char* const lawHtml = R"(<p>OpenFOAM's sixDoF sphericalAngularSpring
restraint between A and B: a moment that turns A back towards its reference
orientation <code>referenceOrientation</code> (Q0) relative to B about every
axis. In B's frame, with R = B.R<sup>T</sup> A.R:</p>
<pre>
m = -stiffness sum over i of (Q0 e_j) x (R e_j - ((Q0 e_i) . R e_j) Q0 e_i),
    j = i + 1 (3 + 1 = 1)
A.M = B.R (m - damping w_rel),  B.M = -A.M,  A.F = B.F = 0
w_rel = B.R^T (A.omega - B.omega)
potentialEnergy = stiffness (1 - cos theta),  theta the angle of Q0^T R
dissipatedPower = damping |w_rel|^2
</pre>
<p>The moment is not conservative at finite angles: potentialEnergy is that
of its conservative part, -stiffness sin(theta) about the turn's axis; the
rest, at most stiffness (1 - cos theta) / sqrt(3), does work around closed
loops of rotations (zero for turns about an axis of Q0). To the fixed world
it is OpenFOAM's restraint with referenceOrientation. stiffness and damping
must be finite and &ge; 0, referenceOrientation a rotation tensor as
OpenFOAM checks it (checked in fmi2ExitInitializationMode).</p>)";

class SphericalAngularSpringModel final
    : public fmuExport::LawFmuModel<connectors::SphericalAngularSpring,
                                    Parameters> {
public:
    SphericalAngularSpringModel()
        : LawFmuModel({"sphericalAngularSpring",
                       "OpenFOAM's sphericalAngularSpring: a moment about "
                       "every axis towards a reference orientation",
                       "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        const Block reference = referenceOrientation();
        const Block stiffness = parameter(&Parameters::stiffness, "stiffness",
                                          "N.m/rad", "stiffness k, >= 0", 10.0);
        const Block damping = parameter(&Parameters::damping, "damping",
                                        "N.m.s/rad", "damping c, >= 0", 0.0);
        OutputDependencies d
            = pointToPointDependencies({reference, stiffness, damping});
        d.tension = {};
        d.potentialEnergy = join(positionBlocks(), {reference, stiffness});
        declareOutputs(d);
        declareStartAtRest();
    }
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<SphericalAngularSpringModel>();
}

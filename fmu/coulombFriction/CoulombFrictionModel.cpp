// coulombFriction.fmu: connectors::CoulombFriction behind the connector FMU
// interface. The variable table below is the only list of its variables.
#include "LawFmuModel.hpp"
#include "coulombFriction/CoulombFriction.hpp"

namespace {

using fmuExport::Block;
using fmuExport::Shape;

const char* const lawHtml = R"(<p>Regularised Coulomb friction at the contact
point P (<code>A.p</code> on A) sliding on body B (or the world). With u the
velocity of A's point P relative to B's material point at P, a the unit
vector of <code>B.axis</code> turned with B, u<sub>t</sub> = (a . u) a
(u<sub>t</sub> = u when <code>B.axis</code> = 0: friction in every
direction), F<sub>c</sub> = frictionForce and v<sub>s</sub> =
regularisationVelocity:</p>
<pre>
A.F = -F_c u_t / sqrt(|u_t|^2 + v_s^2)  (at P),  B.F = -A.F (at P)  [N]
A.M = (P - A.r) x A.F,   B.M = (P - B.r) x B.F                  [N.m]
dissipatedPower = F_c |u_t|^2 / sqrt(|u_t|^2 + v_s^2) &ge; 0    [W]
potentialEnergy = 0
slidingVelocity = a . u (|u| without axis),  friction = A.F . a (|A.F|)
</pre>
<p>length, lengthRate and tension (A.F along P-&gt;Q) use Q
(<code>B.p</code> on B), a reference point on the guide; the loads do
not. frictionForce must be finite and &ge; 0, regularisationVelocity
finite and &gt; 0, B.axis zero or of length &ge; 1e-12 (checked in
fmi2ExitInitializationMode).</p>)";

using Parameters = connectors::CoulombFrictionParameters;

class CoulombFrictionModel final
    : public fmuExport::LawFmuModel<connectors::CoulombFriction, Parameters> {
public:
    CoulombFrictionModel()
        : LawFmuModel({"coulombFriction",
                       "Regularised Coulomb friction of a point of A "
                       "sliding on B, along a guide or in every "
                       "direction",
                       "1.0.0", lawHtml},
                      wording())
    {
        declareBodies({1, 0, 0});
        B_axis_ = parameter(&Parameters::axis_B, "B.axis", "1",
                            "sliding direction (guide), B's frame, "
                            "normalised; 0: every direction",
                            {0, 0, 0});
        frictionForce_
            = parameter(&Parameters::frictionForce, "frictionForce", "N",
                        "Coulomb (sliding) friction force F_c, >= 0", 0.3);
        regularisationVelocity_ = parameter(
            &Parameters::regularisationVelocity, "regularisationVelocity",
            "m/s", "regularisation velocity v_s, > 0", 1e-3);
        const OutputDependencies d = pointToPointDependencies(
            {B_axis_, frictionForce_, regularisationVelocity_});
        declareOutputs(d);
        extraOutput("slidingVelocity", Shape::scalar, "m/s",
                    "velocity of P relative to B along B.axis (its magnitude "
                    "without an axis)",
                    join(d.lengthRate, {B_axis_}));
        extraOutput("friction", Shape::scalar, "N",
                    "friction force on A along B.axis (its magnitude without "
                    "an axis)",
                    d.loads);
        declareStartAtRest();
    }

protected:
    fmuExport::ConnectorOutputs
    evaluate(const double*, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const override
    {
        const connectors::CoulombFrictionResult r = law().evaluateSliding(A, B);
        return {r.loads, {r.slidingVelocity, r.friction}};
    }

private:
    static fmuExport::ConnectorWording wording()
    {
        fmuExport::ConnectorWording w;
        w.noun = "friction";
        w.A_p = "contact point on A, where the friction acts";
        w.B_p = "reference point on B (the guide), for length and tension "
                "only";
        return w;
    }

    Block B_axis_, frictionForce_, regularisationVelocity_;
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<CoulombFrictionModel>();
}

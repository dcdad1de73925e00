#include "LawDescription.hpp"

namespace mooringLineFmu {

const char* const lawHtml = R"(<p>A dynamic lumped-mass mooring line (after
MoorDyn) between the fairlead P (<code>A.p</code> on A) and Q
(<code>B.p</code> on B): an anchor on the seabed (<code>seabedContact</code>
= 1, the seabed is the horizontal plane through Q) or a fairlead on a second
body. N = <code>segments</code> segments of unstretched length L/N; node 0 is
Q, node N is P, the N-1 free nodes carry one segment's mass each:</p>
<pre>
segment tension  T = EA max(e, 0) + axialDamping de/dt,  e = strain
node             (mass + added mass) a = T_i q_i - T_i-1 q_i-1 + E_i
E_i              = -(weight - buoyancy) + seabed penalty and friction
                   + Morison drag relative to the water (current + flow)
A.F = -T_N-1 q_N-1 + E_N,   B.F = T_0 q_0 + E_0   (the ends' half segments)
</pre>
<p>The water moves with the current profile (<code>current.surface</code>
at <code>waterLevel</code>, <code>current.seabed</code> at the height of
B.p, linear between) plus the inputs <code>shape.Ux/Uy/Uz[k]</code>: the
water velocity at the points of the shape outputs of the previous step,
held over the step and interpolated along the line. Their change over the
previous step is the flow's acceleration a, held over the step: with
<code>flowInertia</code> = 1 (default) it acts on the line as
(1 + Ca) rho V a, normal and tangential (Froude-Krylov and added mass);
with <code>flowInertia</code> = 2 a is the inputs
<code>shape.Ax/Ay/Az[k]</code> instead, the water's acceleration at the
same points at the start of the step.
<code>freeSurface</code> = 1 removes buoyancy, drag and added mass above
<code>waterLevel</code>. <code>seabedFriction</code> adds Coulomb friction
on the seabed, regularised below <code>frictionVelocity</code>,
<code>axialFrictionRatio</code> times it along the line, up to
<code>staticFrictionScale</code> times it below that speed.</p>
<p>Up to 4 sections from B.p to A.p: the first is the line of the parameters
above, sections 2 to 4 have their own (<code>section2.EA</code>, ...;
<code>section&lt;k&gt;.unstretchedLength</code> = 0: no section k), with a
point (clump weight or buoy: <code>joint&lt;k&gt;.mass</code>,
<code>volume</code>, <code>dragArea</code>, <code>addedMass</code>) at each
joint; outputs <code>section.lowerTension</code>,
<code>section.upperTension</code> and the joints' positions
<code>joint.x/y/z</code>.</p>
<p>Inside each fmi2DoStep the node states are integrated by the implicit
trapezoidal rule (<code>integrator</code> = 0, the default: one step per
coupling step, or substeps no longer than <code>maxStep</code>, each one
Newton solve with the line's block-tridiagonal matrix, a step halved where
its predictor misses) or by SUNDIALS CVODE (<code>integrator</code> = 1:
BDF, banded direct solver, tolerances <code>relativeTolerance</code>,
<code>absoluteTolerance</code>, restarted at every step), the ends moving
along the cubic Hermite path through their positions and velocities at the
start of the step (saved in the FMU state) and at its end (the inputs): set
the inputs to the end-of-step positions and velocities before fmi2DoStep.
Either integrator starts each step from the node states alone, so a step
repeated from a saved FMU state is identical to the uninterrupted one. The
line starts at rest in the static equilibrium of its own discrete equations
(found by Newton from the quasi-static catenary shape through the
attachment points) at fmi2ExitInitializationMode. SUNDIALS is linked into
the binary: the FMU needs nothing installed beside it.</p>
<p>Energy: <code>kineticEnergy</code>, and since
fmi2ExitInitializationMode the work done on the line at its ends
(<code>fairleadWork</code>, <code>anchorWork</code>), by the moving water
(<code>waterWork</code>) and by the added mass turning with the line
(<code>addedMassWork</code>), and the energy it dissipated
(<code>dissipatedEnergy</code> = <code>dragDissipated</code> +
<code>seabedDissipated</code> + <code>axialDissipated</code>; per section
<code>section.*[k]</code>), in the integrator's own terms over its
internal steps: their work equals the change of
<code>kineticEnergy</code> + <code>potentialEnergy</code> plus
<code>dissipatedEnergy</code>. Details: connectors/mooringLine/README.md.</p>)";

} // namespace mooringLineFmu

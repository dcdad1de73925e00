"""Two-body oscillators joined by the spring and damper FMUs, against their
analytic solutions.

Bodies of mass M1 and M2 on prismatic x joints (rigidBodySim) or free
(fmusim twobody), joined at their centres; s is the extension x2 - x1 - L0
and mu = M1 M2 / (M1 + M2) the reduced mass:
- spring (linearSpring, c = 0): s = S0 cos(w t), w = sqrt(K / mu);
- spring-damper (linearSpring, c = 2 ZETA sqrt(K mu)):
  s = S0 exp(-ZETA w t) (cos(wd t) + ZETA w / wd sin(wd t)), wd = w sqrt(1 - ZETA^2);
- damper (linearDamper, relative velocity U0 at t = 0):
  s = S0 + U0 TAU (1 - exp(-t / TAU)), TAU = mu / C.
The error is the largest |s - s_exact| over the run, relative to S0 (spring)
or to the travel U0 TAU (damper).
"""
import math

from foamfmi.bridgecase import fmu_restraint, rigid_body_model
from vcommon import fmu_path, run_fmusim, run_rigid, slider, solver_entry

M1, M2, K, L0, S0 = 2.0, 3.0, 50.0, 1.0, 0.1
MU = M1 * M2 / (M1 + M2)
OMEGA = math.sqrt(K / MU)
PERIOD = 2 * math.pi / OMEGA
ZETA = 0.1
U0, TAU = 0.5, 0.5

# (label, runner, solver, nIter)
SCHEMES = (
    ("symplectic", "rigid", "symplectic", 1),
    ("Newmark x3", "rigid", "Newmark", 3),
    ("implicitNewmark", "rigid", "implicitNewmark", 1),
    ("fmusim explicit", "fmusim", "explicit", 1),
    ("fmusim implicit", "fmusim", "implicit", 1),
)


def case_setup(connector, m1=M1, m2=M2, k=K, c=None):
    """(fmu, parameters, s0, u0, exact s(t), scale of the error, time unit);
    c: the damper's coefficient (default mu / TAU)."""
    mu = m1 * m2 / (m1 + m2)
    if connector == "damper":
        c = mu / TAU if c is None else c
        tau = mu / c
        return ("linearDamper", {"damping": c}, 0.0, U0,
                lambda t: U0 * tau * (1 - math.exp(-t / tau)), U0 * tau, tau)
    w = math.sqrt(k / mu)
    zeta = ZETA if connector == "spring-damper" else 0.0
    c = 2 * zeta * math.sqrt(k * mu)
    wd = w * math.sqrt(1 - zeta**2)

    def exact(t):
        return S0 * math.exp(-zeta * w * t) * (math.cos(wd * t) + zeta * w / wd * math.sin(wd * t))

    return ("linearSpring", {"stiffness": k, "restLength": L0, "damping": c},
            S0, 0.0, exact, S0, 2 * math.pi / w)


def rigid_model(solver, fmu, params, s0, u0, m1, m2):
    return rigid_body_model(
        slider("body1", m1, (0, 0, 0), "Px") + slider("body2", m2, (L0 + s0, 0, 0), "Px"),
        fmu_restraint("connector", fmu_path(fmu), "body1", {**params, "A.p": "(0 0 0)", "B.p": "(0 0 0)"},
                      "body2"),
        solver_entry(solver), extra=f"    qDot (0 {u0!r});\n")


def run(connector, scheme, dt, end, m1=M1, m2=M2, k=K, c=None):
    """One run: (Outcome, times, s) with s the extension at every step."""
    _, runner, solver, n_iter = scheme
    fmu, params, s0, u0, _, _, _ = case_setup(connector, m1, m2, k, c)
    if runner == "rigid":
        out = run_rigid("verification", rigid_model(solver, fmu, params, s0, u0, m1, m2),
                        end, dt, n_iter)
        if not out.ok:
            return out, [], []
        b = out.bodies
        return out, b["Time"], [x2 - x1 - L0 for x1, x2 in zip(b["body1.c.x"], b["body2.c.x"])]
    options = {"scheme": solver, "step-size": dt, "stop-time": end, "A.mass": m1, "B.mass": m2,
               "B.position": (L0 + s0, 0, 0), "B.velocity": (u0, 0, 0)}
    # Both attachments at the bodies' centres, as in the rigid-body model
    # (the FMUs' own B.p starts 1 m off, for a connector to the world)
    at_centres = {f"{side}.p[{i}]": 0.0 for side in "AB" for i in (1, 2, 3)}
    out = run_fmusim(fmu, options, {**at_centres, **params})
    if not out.ok:
        return out, [], []
    t = out.table
    return out, t["time"], [x2 - x1 - L0 for x1, x2 in zip(t["A.x"], t["B.x"])]


def error(connector, times, s, m1=M1, m2=M2, k=K, c=None):
    *_, exact, scale, _ = case_setup(connector, m1, m2, k, c)
    if not s:
        return float("inf")
    e = max(abs(x - exact(t)) for t, x in zip(times, s))
    return e / scale if math.isfinite(e) else float("inf")


def work_precision(connector, scheme, steps_per_unit, units=10):
    """Rows (steps per period or per TAU, dt, steps, CPU time, error) over
    `units` periods (spring) or time constants (damper)."""
    *_, unit = case_setup(connector)
    rows = []
    for n in steps_per_unit:
        dt = unit / n
        out, times, s = run(connector, scheme, dt, units * unit)
        rows.append((n, dt, n * units, out.cpu, error(connector, times, s) if out.ok else float("inf")))
    return rows

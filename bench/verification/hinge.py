"""The hinge FMU against exact revolute joints.

Work-precision: the double pendulum of tests/bridge/test_hinge.py (two
rods on two hinge FMUs, 6 DoF each, and the same pendulum on OpenFOAM's Ry
joints in the same model), run with a solver, a penalty stiffness k and a
step dt; the error is the largest distance between the centres of mass of
the hinged rods and those of the exact-joint rods of a reference run
(implicitNewmark, second order from the start, DT_REF), over END seconds.

Stability: one rod (mass M, inertia I about its centre, centre D below
the hinge point) hanging from the world on a hinge FMU, released from rest
under gravity tilted by 0.5 rad, no penalty damping, rotational penalty
k D^2. The dimensionless stiffness is k dt^2 / m_eff, m_eff = M J / (1 + J)
the mass felt across the rod at the hinge point, J = I / (M D^2). Stable:
the run completes and the gap stays below GAP_FACTOR times the static gap
M G / k (the undamped penalty modes excited at the release swing the gap
to about twice it; an unstable run grows without bound).
"""
import math
import os
import sys

from foamfmi.bridgecase import fmu_restraint, rigid_body, rigid_body_model
from vcommon import TOP, fmu_path, has_nan, run_rigid, solver_entry

# The double pendulum itself
sys.path.insert(0, os.path.join(TOP, "tests", "bridge"))
import test_hinge  # noqa: E402

END, DT_REF = 0.5, 5e-5
RODS = (("e1", "f1"), ("e2", "f2"))
M, D, G, ALPHA = 2.0, 0.25, 9.81, 0.5
GAP_FACTOR = 10.0
STABILITY_DT, STABILITY_STEPS = 1e-3, 1000


def pendulum_model(solver, k):
    return test_hinge.model(k).replace("solver { type symplectic; }", solver_entry(solver))


def reference():
    """Times and centres of the exact-joint rods, fine step."""
    out = run_rigid("hingeRef", pendulum_model("implicitNewmark", 1e6), END, DT_REF)
    if not out.ok:
        raise RuntimeError(f"hinge reference failed: {out.message}")
    b = out.bodies
    return b["Time"], {e: [b[f"{e}.c.{c}"] for c in "xyz"] for e, _ in RODS}


def interpolate(times, values, t):
    i = min(max(int(round(t / (times[1] - times[0]))), 0), len(times) - 2)
    while i > 0 and times[i] > t:
        i -= 1
    while i < len(times) - 2 and times[i + 1] < t:
        i += 1
    w = (t - times[i]) / (times[i + 1] - times[i])
    return values[i] + w * (values[i + 1] - values[i])


def pendulum_error(ref, solver, n_iter, k, dt):
    """(Outcome, largest |c_hinged - c_exact,ref| in m)."""
    times, centres = ref
    out = run_rigid("hinge", pendulum_model(solver, k), END, dt, n_iter)
    if not out.ok:
        return out, float("inf")
    b = out.bodies
    err = 0.0
    for e, f in RODS:
        for j, c in enumerate("xyz"):
            for t, x in zip(b["Time"], b[f"{f}.c.{c}"]):
                err = max(err, abs(x - interpolate(times, centres[e][j], t)))
    return out, err if math.isfinite(err) else float("inf")


def rod_model(solver, k, inertia_ratio):
    inertia = inertia_ratio * M * D**2
    g = (-G * math.sin(ALPHA), 0, -G * math.cos(ALPHA))
    hinge = fmu_restraint("hinge", fmu_path("hinge"), "rod", {
        "A.p": (0, 0, D), "B.p": "(0 0 0)", "A.axis": "(0 1 0)", "B.axis": "(0 1 0)",
        "stiffness": k, "damping": 0, "rotationalStiffness": k * D**2, "rotationalDamping": 0})
    return rigid_body_model(rigid_body("rod", M, inertia, (0, 0, -D), "floating"), hinge,
                            solver_entry(solver), g=g)


def m_eff(inertia_ratio):
    return M * inertia_ratio / (1 + inertia_ratio)


def rod_stability(solver, n_iter, ratio, inertia_ratio, dt=STABILITY_DT):
    """(outcome, message) of the hanging rod at k dt^2 / m_eff = ratio."""
    k = ratio * m_eff(inertia_ratio) / dt**2
    out = run_rigid("hingeStability", rod_model(solver, k, inertia_ratio),
                    STABILITY_STEPS * dt, dt, n_iter, connectors=("hinge",))
    if not out.ok:
        return "failed", out.message
    gap = out.table["hinge"]["gap"]
    if has_nan(out.bodies) or has_nan(out.table["hinge"]):
        return "nan", ""
    return ("stable" if max(gap) < GAP_FACTOR * M * G / k else "unstable"), ""

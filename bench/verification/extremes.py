"""Extreme cases: each gives a correct result (checked against its exact
answer) or a clear error; a non-finite number in any output is a failure.

Rows: (case, connector, tool, outcome, detail); outcome is 'correct',
'clear error', 'wrong' or 'NaN'.
"""
import math
import subprocess

import catenary as cat
import oscillator as osc
from vcommon import FMUSIM, fmu_path, has_nan, run_fmusim, run_rigid

IMPLICIT = ("implicitNewmark", "rigid", "implicitNewmark", 1)
SYMPLECTIC = ("symplectic", "rigid", "symplectic", 1)
FMUSIM_IMPLICIT = ("fmusim implicit", "fmusim", "implicit", 1)


def judged(out, error, bound, what):
    """A row's outcome and detail from an Outcome and an error against the
    exact answer; bound: the error the scheme must reach."""
    if not out.ok:
        return "clear error", out.message
    tables = [out.bodies] if out.bodies else [out.table]
    if any(has_nan(t) for t in tables if t):
        return "NaN", "non-finite output"
    ok = error <= bound
    return ("correct" if ok else "wrong"), f"{what} {error:.1e} (bound {bound:.0e})"


def spring_against_exact(scheme, dt, periods, m1=osc.M1, m2=osc.M2, bound=None):
    mu = m1 * m2 / (m1 + m2)
    period = 2 * math.pi / math.sqrt(osc.K / mu)
    out, t, s = osc.run("spring", scheme, dt, periods * period, m1, m2)
    err = osc.error("spring", t, s, m1, m2) if out.ok else float("inf")
    # bound: the trapezoidal rule's phase error (w dt)^2/12 per radian,
    # accumulated over the run (2 pi periods radians), times 2 for margin
    w_dt = dt * math.sqrt(osc.K / mu)
    bound = bound if bound is not None else 2 * (w_dt**2 / 12) * 2 * math.pi * periods + 1e-9
    return judged(out, err, bound, "max error of s / S0")


def zero_length_spring():
    """restLength 0, the bodies pass through each other: s = x2 - x1 =
    S0 cos(w t) through zero length."""
    mu = osc.MU
    w = math.sqrt(osc.K / mu)
    dt = 2 * math.pi / w / 200
    options = {"scheme": "implicit", "step-size": dt, "stop-time": 2 * 2 * math.pi / w,
               "A.mass": osc.M1, "B.mass": osc.M2, "B.position": (osc.S0, 0, 0)}
    out = run_fmusim("linearSpring", options, {"stiffness": osc.K, "restLength": 0, "damping": 0})
    if not out.ok:
        return "clear error", out.message
    t = out.table
    err = max(abs(xb - xa - osc.S0 * math.cos(w * tt)) for tt, xa, xb in zip(t["time"], t["A.x"], t["B.x"]))
    bound = 2 * ((w * dt) ** 2 / 12) * 2 * math.pi * 2
    return judged(out, err / osc.S0, bound, "max error of s / S0")


def coincident(tool):
    """Attachment points on top of each other with a rest length > 0."""
    params = {"stiffness": osc.K, "restLength": 0.5, "damping": 0}
    if tool == "fmusim":
        out = run_fmusim("linearSpring", {"stop-time": 0.1, "step-size": 0.01,
                                          "B.position": (0, 0, 0)}, params)
    else:
        model = osc.rigid_model("symplectic", "linearSpring", params, -osc.L0, 0.0, osc.M1, osc.M2)
        out = run_rigid("coincident", model, 0.1, 0.01)
    return judged(out, float("inf"), 0, "ran on")


def spinning_spring():
    """A body spinning at 20 rad/s, held to a free body by a spring at an
    off-centre point, implicit (trapezoidal) coupling at 0.2 and 0.1 rad per
    step: the energy error must be bounded and fall at second order
    (observed order above 1.6: the scheme is second order, not exactly
    conservative for this nonlinear problem)."""
    drifts = []
    for h in (0.01, 0.005):
        options = {"scheme": "implicit", "step-size": h, "stop-time": 5,
                   "A.angular-velocity": (0, 0, 20), "A.inertia": (1, 1, 1)}
        out = run_fmusim("linearSpring", options, {"stiffness": 50, "restLength": 1, "damping": 0,
                                                   "A.p[1]": 0.5, "B.p[1]": 2.0})
        if not out.ok:
            return "clear error", out.message
        t = out.table
        e = [ka + kb + p for ka, kb, p in
             zip(t["A.kineticEnergy"], t["B.kineticEnergy"], t["potentialEnergy"])]
        drifts.append(max(abs(x - e[0]) for x in e) / e[0])
    p = math.log2(drifts[0] / drifts[1])
    outcome, _ = judged(out, 1.6 - p, 0, "")
    return outcome, (f"largest |E - E0| / E0 {drifts[0]:.1e} (0.2 rad/step), "
                     f"{drifts[1]:.1e} (0.1 rad/step): order {p:.2f} (bound: above 1.6)")


def spinning_hinge():
    """A body turning 16 times about the hinge axis (10 rad/s, 10 s): the
    hinge's unwrapped angle output must follow 10 t."""
    options = {"scheme": "implicit", "step-size": 0.01, "stop-time": 10,
               "A.angular-velocity": (0, 10, 0)}
    out = run_fmusim("hinge", options, {"A.axis[1]": 0, "A.axis[2]": 1, "A.axis[3]": 0,
                                        "B.axis[1]": 0, "B.axis[2]": 1, "B.axis[3]": 0,
                                        "B.p[1]": 0, "B.p[2]": 0, "B.p[3]": 0})
    if not out.ok:
        return "clear error", out.message
    t = out.table
    err = max(abs(abs(a) - 10 * tt) for tt, a in zip(t["time"], t["angle"]))
    return judged(out, err, 1e-9 * 100, "largest ||angle| - 10 t| [rad]")


def nan_check(fmu):
    r = subprocess.run([FMUSIM, "check", fmu_path(fmu)], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    line = next((ln for ln in r.stdout.splitlines() if "non-finite-inputs" in ln), "no such check")
    return ("clear error" if line.startswith("PASS") else "wrong"), line


def nan_parameter():
    model = osc.rigid_model("symplectic", "linearSpring",
                            {"stiffness": "nan", "restLength": osc.L0, "damping": 0},
                            osc.S0, 0.0, osc.M1, osc.M2)
    out = run_rigid("nanParameter", model.replace("stiffness 'nan'", "stiffness nan"), 0.1, 0.01)
    return judged(out, float("inf"), 0, "ran on")


def catenary_error(name, params, fairlead):
    full = {"unstretchedLength": cat.L, "EA": cat.EA, **params}
    table, message, _ = cat.fmusim_run("catenary", full, [fairlead, fairlead], ["H", "V"])
    if table is None:
        return "clear error", message
    return "wrong", f"returned H = {table['H'][-1]:.3g} N"


def catenary_folded(params, fairlead):
    """A slack line with both ends on one vertical folds: no horizontal
    tension, and the fairlead carries part of the line's weight (all of it
    would mean no line on the anchor side, none a line hanging from below)."""
    full = {"unstretchedLength": cat.L, "EA": cat.EA, **params}
    table, message, _ = cat.fmusim_run("catenary", full, [fairlead, fairlead], ["H", "V"])
    if table is None:
        return "clear error", message
    h, v = table["H"][-1], table["V"][-1]
    ok = h == 0 and 0 < v <= cat.W * cat.L
    return ("correct" if ok else "wrong"), f"folded: H = {h:.3g} N, V = {v:.4g} N of wL = {cat.W * cat.L:.4g} N"


def rows():
    out = []
    add = out.append
    add(("zero-length spring (restLength 0, through zero length)", "linearSpring", "fmusim implicit",
         *zero_length_spring()))
    add(("coincident attachment points, restLength 0.5 m", "linearSpring", "fmusim", *coincident("fmusim")))
    add(("coincident attachment points, restLength 0.5 m", "linearSpring", "rigidBodySim",
         *coincident("rigid")))
    add(("large rotations: 20 rad/s, 0.2 rad per step", "linearSpring", "fmusim implicit",
         *spinning_spring()))
    add(("large rotations: 16 turns about the hinge axis", "hinge", "fmusim implicit", *spinning_hinge()))
    for ratio in (1e-3, 1e3):
        for scheme in (SYMPLECTIC, IMPLICIT):
            mu = osc.M1 * ratio * osc.M1 / (osc.M1 + ratio * osc.M1)
            dt = 2 * math.pi / math.sqrt(osc.K / mu) / 100
            bound = 0.2 if scheme is SYMPLECTIC else None
            add((f"mass ratio m2/m1 = {ratio:g}, 100 steps per period", "linearSpring", scheme[0],
                 *spring_against_exact(scheme, dt, 5, osc.M1, ratio * osc.M1, bound)))
    for dt in (1e-6, 0.1):
        for scheme in (SYMPLECTIC, IMPLICIT, FMUSIM_IMPLICIT):
            periods = 0.02 if dt == 1e-6 else 5
            bound = (0.05 if dt == 1e-6 else 0.5) if scheme is SYMPLECTIC else None
            add((f"time step {dt:g} s (k dt^2/mu = {osc.K * dt**2 / osc.MU:.2g})", "linearSpring",
                 scheme[0], *spring_against_exact(scheme, dt, periods, bound=bound)))
    for fmu in ("linearSpring", "linearDamper", "translationalDamper", "rotationalDamper", "axialAngularSpring",
                "tabulatedAxialAngularSpring", "sphericalAngularSpring", "hinge", "catenary"):
        add(("NaN or infinite kinematic input (fmusim check)", fmu, "FMU C API", *nan_check(fmu)))
    add(("NaN stiffness in the case", "linearSpring", "rigidBodySim", *nan_parameter()))
    susp = {"weight": cat.W, "seabedContact": 1, "seabedFriction": 0}
    add(("catenary: fairlead below the seabed", "catenary", "fmusim run",
         *catenary_error("below", susp, (50.0, 0.0, -1.0))))
    add(("catenary: slack line, both ends on one vertical, no seabed", "catenary", "fmusim run",
         *catenary_folded({**susp, "seabedContact": 0}, (0.0, 0.0, 50.0))))
    return out

"""The catenary FMU (quasi-static line) against the closed-form catenary,
moored-body dynamics against a converged solution, and the stability of a
taut vertical line.

Quasi-static: for given fairlead tensions H, V the spans x, z follow in
closed form (connectors/catenary/README.md, Irvine 1981); placing the
fairlead there, the FMU must return H and V. Error: max(|dH|, |dV|) over the
fairlead tension.

Dynamics: a body of mass MB on a prismatic x joint between two identical
lines to anchors at (+-XA, 0, -ZA), released OFFSET from the centre; the
error is the largest |x - x_ref| over two surge periods relative to
OFFSET, x_ref from implicitNewmark at a 16 times smaller step.

Stability: a tension leg, a body on a prismatic z joint held by a vertical
weightless line of stiffness EA/L against a lift m g (the line stays
taut); k dt^2/m = EA dt^2 / (L m).
"""
import csv
import math
import os
import subprocess
import tempfile

from foamfmi.bridgecase import fmu_restraint, rigid_body_model
from vcommon import FMUSIM, child_cpu, fmi_message, fmu_path, has_nan, run_rigid, slider, solver_entry

L, EA, W = 100.0, 5e7, 700.0


def spans_suspended(h, v, w, length=L, ea=EA):
    a, b = v / h, (v - w * length) / h
    if w == 0:
        t = math.hypot(h, v)
        return h * length / t + h * length / ea, v * length / t + v * length / ea
    x = h / w * (math.asinh(a) - math.asinh(b)) + h * length / ea
    z = h / w * (math.sqrt(1 + a * a) - math.sqrt(1 + b * b)) + (v * length - w * length**2 / 2) / ea
    return x, z


def spans_touchdown(h, v, w, cb, length=L, ea=EA):
    lb = length - v / w
    a = v / h
    x = lb + h / w * math.asinh(a) + h * length / ea
    if cb > 0:
        x += cb * w / (2 * ea) * (-lb**2 + (lb - h / (cb * w)) * max(lb - h / (cb * w), 0))
    z = h / w * (math.sqrt(1 + a * a) - 1) + v * v / (2 * ea * w)
    return x, z


def quasi_static_cases():
    """(case, parameters, [(x, z, H, V)])"""
    susp = {"weight": W, "seabedContact": 0, "seabedFriction": 0}
    cases = [
        ("suspended, two fairleads", susp,
         [(*spans_suspended(h, v, W), h, v) for h, v in ((2e4, 9e4), (5e4, 3e4), (1e3, 7.1e4))]),
        ("lifting off (anchor tension rising)", {**susp, "seabedContact": 1},
         [(*spans_suspended(h, W * L * f, W), h, W * L * f) for h, f in ((2e4, 1.001), (2e4, 1.05))]),
        ("touchdown, no friction", {**susp, "seabedContact": 1},
         [(*spans_touchdown(h, v, W, 0), h, v) for h, v in ((2e4, 4e4), (5e3, 2e4), (1e5, 6.9e4))]),
        ("touchdown, friction 0.5", {**susp, "seabedContact": 1, "seabedFriction": 0.5},
         [(*spans_touchdown(h, v, W, 0.5), h, v) for h, v in ((2e4, 4e4), (5e3, 2e4), (1e2, 3e4))]),
        ("taut (stretched 0.5 %)", susp,
         [(*spans_suspended(h, v, W), h, v) for h, v in ((2.5e5, 2e5), (1e5, 2.5e5))]),
        ("buoyant line (w = -200 N/m)", {**susp, "weight": -200},
         [(*spans_suspended(h, v, -200), h, v) for h, v in ((1e4, -3e4), (1e4, 5e3))]),
        ("weightless line", {**susp, "weight": 0},
         [(*spans_suspended(h, v, 0), h, v) for h, v in ((1e5, 1e5), (2e5, 1e4))]),
    ]
    # vertical and taut: H = 0, V = (z - L) EA/L + w L/2
    cases.append(("vertical, taut", susp,
                  [(0.0, z, 0.0, (z - L) * EA / L + W * L / 2) for z in (100.5, 101.0)]))
    # slack on the seabed: the hanging length Ls solves z = Ls + w Ls^2/(2 EA), V = w Ls
    zs = 40.0
    ls = (-1 + math.sqrt(1 + 2 * W * zs / EA)) * EA / W
    cases.append(("slack on the seabed", {**susp, "seabedContact": 1}, [(30.0, zs, 0.0, W * ls)]))
    return cases


def fmusim_run(fmu, params, rows, outputs, step=1.0):
    """fmusim run with an input table of A.r rows (one per step), B at the
    origin; returns
    (columns or None, message, CPU seconds)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.csv")
        with open(path, "w") as f:
            f.write("time,A.r[1],A.r[2],A.r[3],B.r[1],B.r[2],B.r[3]\n")
            for i, r in enumerate(rows):
                f.write(f"{i * step!r},{r[0]!r},{r[1]!r},{r[2]!r},0,0,0\n")
        args = [FMUSIM, "run", fmu_path(fmu), "--start-time", "0", "--stop-time",
                repr((len(rows) - 1) * step), "--step-size", repr(step), "--input-file", path,
                "--output-variables", ",".join(outputs)]
        for key, value in params.items():
            args += ["--set", f"{key}={value!r}"]
        cpu0 = child_cpu()
        r = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        cpu = child_cpu() - cpu0
    if r.returncode != 0:
        return None, fmi_message(r.stderr), cpu
    table = list(csv.reader(r.stdout.splitlines()))
    return {n: [float(x[i]) for x in table[1:]] for i, n in enumerate(table[0])}, "", cpu


def quasi_static():
    """Rows (case, x, z, H, V, error)."""
    rows = []
    for name, params, points in quasi_static_cases():
        full = {"unstretchedLength": L, "EA": EA, **params}
        inputs = [(x, 0.0, z) for x, z, _, _ in points]
        table, message, _ = fmusim_run("catenary", full, [inputs[0]] + inputs, ["H", "V"])
        for i, (x, z, h, v) in enumerate(points):
            if table is None:
                rows.append((name, x, z, h, v, float("inf"), message))
                continue
            err = max(abs(table["H"][i + 1] - h), abs(table["V"][i + 1] - v)) / math.hypot(h, v)
            rows.append((name, x, z, h, v, err, ""))
    return rows


def cost_per_call(fmu, params, path, calls=20000):
    """CPU seconds per fmi2DoStep along a fairlead path(t) in [0, 1],
    fmusim's start-up (a run of one step) removed."""
    rows = [path(i / calls) for i in range(calls + 1)]
    _, _, base = fmusim_run(fmu, params, rows[:2], ["A.F[1]"])
    table, message, cpu = fmusim_run(fmu, params, rows, ["A.F[1]"])
    if table is None:
        raise RuntimeError(message)
    return (cpu - base) / calls


# Moored body
MB, XA, ZA, OFFSET = 2e5, 70.0, 58.0, 5.0
MOORING = {"unstretchedLength": L, "EA": EA, "weight": W, "seabedContact": 1, "seabedFriction": 0}


def moored_model(solver):
    lines = "".join(fmu_restraint(name, fmu_path("catenary"), "body",
                                  {**MOORING, "A.p": "(0 0 0)", "B.p": (sign * XA, 0, -ZA)})
                    for name, sign in (("east", 1), ("west", -1)))
    return rigid_body_model(slider("body", MB, (OFFSET, 0, 0), "Px"), lines, solver_entry(solver),
                            g=(0, 0, -9.81))


def surge_period():
    """From the surge stiffness of the pair of lines at the centre, by a
    central difference of H through the FMU."""
    dx = 0.01
    rows = [(XA + dx, 0, ZA), (XA - dx, 0, ZA)]
    table, message, _ = fmusim_run("catenary", MOORING, [rows[0]] + rows, ["H"])
    if table is None:
        raise RuntimeError(message)
    k = 2 * (table["H"][1] - table["H"][2]) / (2 * dx)
    return 2 * math.pi * math.sqrt(MB / k)


def moored(solver, n_iter, dt, end):
    out = run_rigid("moored", moored_model(solver), end, dt, n_iter)
    if not out.ok:
        return out, [], []
    return out, out.bodies["Time"], out.bodies["body.c.x"]


def tension_leg_model(solver, ratio, dt, mass=1.0, x0=0.01):
    """Returns (model, z of equilibrium, x0): weightless vertical line,
    stretch at equilibrium 2 x0 under the lift."""
    k = ratio * mass / dt**2
    length = 1.0
    ea = k * length
    lift = 2 * x0 * k
    z_eq = length + 2 * x0
    params = {"unstretchedLength": length, "EA": ea, "weight": 0.0, "seabedContact": 0,
              "seabedFriction": 0}
    model = rigid_body_model(
        slider("body", mass, (0, 0, z_eq + x0), "Pz"),
        fmu_restraint("leg", fmu_path("catenary"), "body", {**params, "A.p": "(0 0 0)", "B.p": "(0 0 0)"}),
        solver_entry(solver), g=(0, 0, lift / mass))
    return model, z_eq, x0


def tension_leg_stability(solver, n_iter, ratio, dt=0.01, growth_limit=2.0):
    model, z_eq, x0 = tension_leg_model(solver, ratio, dt)
    steps = min(5000, max(200, math.ceil(50 * 2 * math.pi / math.sqrt(ratio))))
    out = run_rigid("tensionLeg", model, steps * dt, dt, n_iter)
    if not out.ok:
        return "failed", out.message
    if has_nan(out.bodies):
        return "nan", ""
    grown = max(abs(z - z_eq) for z in out.bodies["body.c.z"]) / x0
    return ("stable" if grown <= growth_limit else "unstable"), ""

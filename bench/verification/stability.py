"""Stability maps of the spring and damper connectors: outcome of a run
against the dimensionless stiffness k dt^2/mu (damping c dt/mu), the mass
ratio and the solver, with OpenFOAM's built-in linearSpring to the world
as the baseline, and the measured limits by bisection.

A run is 'stable' when the largest |extension| (spring) or |relative
velocity| (damper) stays within GROWTH times its initial value over 50
periods (spring; at least 200 and at most 5000 steps) or 200 steps
(damper); 'unstable' when it ran but grew beyond that; 'failed' when the
program stopped with an error (its message is kept); 'nan' if a
non-finite number reached the output (never expected).
"""
import math

import oscillator as osc
from foamfmi.implicitcase import growth, spring_model
from vcommon import has_nan, run_rigid, solver_entry

DT = 0.01
GROWTH = 2.0
DAMPER_STEPS = 200
# The oscillators' schemes and OpenFOAM's Newmark with one solve a step
SOLVERS = osc.SCHEMES[:1] + (("Newmark x1", "rigid", "Newmark", 1),) + osc.SCHEMES[1:]
# theory.py scheme of each solver
THEORY = {label: (solver, n_iter) for label, _, solver, n_iter in SOLVERS}
MASS_RATIOS = (1e-3, 1.0, 1e3)


def window(ratio):
    """Steps of a spring run: 50 periods, within [200, 5000]."""
    return min(5000, max(200, math.ceil(50 * 2 * math.pi / math.sqrt(ratio))))


def classify(out, grown):
    if not out.ok:
        return "failed"
    tables = [out.bodies] + list((out.table or {}).values()) if out.bodies else [out.table]
    if any(has_nan(t) for t in tables if t):
        return "nan"
    return "stable" if grown <= GROWTH else "unstable"


def world_spring(solver, ratio, dt=DT):
    """Built-in linearSpring and the FMU, each holding a 1 kg body to the
    world, in one rigidBodySim run: {row: (outcome, message)}."""
    _, runner, name, n_iter = solver
    if runner != "rigid":
        return {}
    k = ratio / dt**2
    out = run_rigid("stabilityWorld", spring_model(solver_entry(name), k), window(ratio) * dt, dt, n_iter)
    if not out.ok:
        return {"built-in to world": ("failed", out.message), "FMU to world": ("failed", out.message)}
    return {"built-in to world": (classify(out, growth(out.bodies, "builtin")), ""),
            "FMU to world": (classify(out, growth(out.bodies, "fmu")), "")}


def two_body(connector, solver, ratio, mass_ratio, dt=DT):
    """The two-body FMU oscillator (spring: ratio = k dt^2/mu; damper:
    ratio = c dt/mu): (outcome, message)."""
    m1, m2 = 1.0, mass_ratio
    mu = m1 * m2 / (m1 + m2)
    if connector == "damper":
        out, times, s = osc.run("damper", solver, dt, DAMPER_STEPS * dt, m1, m2, c=ratio * mu / dt)
        if not out.ok:
            return "failed", out.message
        v = [(s[i + 1] - s[i]) / (times[i + 1] - times[i]) for i in range(len(s) - 1)]
        return classify(out, max(abs(x) for x in v) / osc.U0 if v else 0.0), ""
    k = ratio * mu / dt**2
    out, times, s = osc.run("spring", solver, dt, window(ratio) * dt, m1, m2, k)
    if not out.ok:
        return "failed", out.message
    return classify(out, max(abs(x) for x in s) / osc.S0), ""


def spring_row_outcomes(solver, ratio, dt=DT):
    """Every row of the spring map at one point."""
    rows = world_spring(solver, ratio, dt)
    for r in MASS_RATIOS:
        rows[f"two bodies m2/m1 = {r:g}"] = two_body("spring", solver, ratio, r, dt)
    return rows


def sweep(point, grid, explicit):
    """Run point(ratio) -> {row: (outcome, message)} over the grid; an
    explicit solver stops after two consecutive points where no row is
    stable (beyond them it only diverges faster)."""
    results, misses = [], 0
    for ratio in grid:
        rows = point(ratio)
        results.append((ratio, rows))
        misses = 0 if any(o == "stable" for o, _ in rows.values()) else misses + 1
        if explicit and misses >= 2:
            break
    return results


def is_stable_spring(solver, row_mass_ratio, dt=DT):
    """A predicate for bisection on one row of the spring map."""
    def stable(ratio):
        if row_mass_ratio is None:
            return world_spring(solver, ratio, dt)["FMU to world"][0] == "stable"
        return two_body("spring", solver, ratio, row_mass_ratio, dt)[0] == "stable"
    return stable


def is_stable_damper(solver, mass_ratio=1.0, dt=DT):
    return lambda ratio: two_body("damper", solver, ratio, mass_ratio, dt)[0] == "stable"

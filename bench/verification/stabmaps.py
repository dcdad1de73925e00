"""Stability maps and measured limits of every connector, with the
theoretical limits of the schemes (theory.py) under the same criterion."""
import os

import catenary as cat
import hinge
import plots
import stability as st
import theory
from studies import DAMPER_GRID, HINGE_GRID, INERTIA_RATIOS, OUT, SPRING_GRID
from vcommon import bisect_limit, write_csv

RIGID_THEORY = {"symplectic": ("symplectic", 1), "Newmark": ("Newmark", 1)}


def theory_limits(label, connector):
    """(window criterion, asymptotic) limits of a solver's recurrence on
    the spring (k dt^2/m) or damper (c dt/m)."""
    scheme, n_iter = st.THEORY[label]
    if connector == "spring":
        window = theory.limit(lambda r: theory.window_growth(scheme, n_iter, r, 0, 1.0, st.window(r))
                              <= st.GROWTH)
        asym = theory.limit(lambda r: theory.spectral_radius(scheme, n_iter, r, 0, 1.0) <= 1 + 1e-9)
    else:
        window = theory.limit(lambda r: theory.window_growth(scheme, n_iter, 0, r, 1.0, st.DAMPER_STEPS,
                                                             x0=0.0, v0=1.0) <= st.GROWTH)
        asym = theory.limit(lambda r: theory.spectral_radius(scheme, n_iter, 0, r, 1.0) <= 1 + 1e-9)
    return window, asym


def measured_limit(results, row, stable_at):
    """Bisect between the last stable and the first non-stable grid point
    of a row; None if the row is stable over the whole grid."""
    last, first = None, None
    for ratio, rows in results:
        if row not in rows:
            continue
        if rows[row][0] == "stable":
            last = ratio
        elif last is not None:
            first = ratio
            break
    if first is None:
        return last, None
    return bisect_limit(stable_at, last, first)


def map_points(results):
    return [(ratio, row, o) for ratio, rows in results for row, (o, _) in rows.items()]


def first_messages(results):
    """The first failure message of each row: what the user sees."""
    seen = {}
    for ratio, rows in results:
        for row, (o, message) in rows.items():
            if o == "failed" and row not in seen:
                seen[row] = (ratio, message)
    return seen


def csv_rows(name, results):
    """(solver, ratio, row, outcome, message) of every run of a map."""
    return [(name, r, row, o, m) for r, rows in results for row, (o, m) in rows.items()]


def labelled_points(out):
    """(ratio, "solver: row", outcome) of every run of every solver's map."""
    return [(x, f"{name}: {row}", o) for name, d in out.items() for x, row, o in map_points(d["results"])]


def until_unstable(grid, rows_at, keep_going):
    """[(ratio, {row: (outcome, message)})] over the grid, stopped after two
    ratios in a row with no stable run unless keep_going."""
    results, misses = [], 0
    for r in grid:
        results.append((r, rows_at(r)))
        misses = 0 if any(o == "stable" for o, _ in results[-1][1].values()) else misses + 1
        if not keep_going and misses >= 2:
            break
    return results


def add_map(out, table, name, results, **more):
    """A solver's map into out (its results, more, its first failure
    messages) and its runs into table, the CSV rows."""
    out[name] = {"results": results, **more, "messages": first_messages(results)}
    table += csv_rows(name, results)


def written(out, rows, name, header, draw, figures):
    """out, after stability-<name>.csv and its figure (draw) when figures."""
    if figures:
        write_csv(os.path.join(OUT, f"stability-{name}.csv"), header, rows)
        draw(out)
    return out


def spring_maps(solvers=st.SOLVERS, grid=SPRING_GRID, figures=True, bisect=True):
    out, table = {}, []
    for solver in solvers:
        explicit = solver[0] not in ("implicitNewmark",)
        results = st.sweep(lambda r: st.spring_row_outcomes(solver, r), grid, explicit)
        limits = {}
        for row in ("FMU to world", "two bodies m2/m1 = 1"):
            mass_ratio = None if row == "FMU to world" else 1.0
            if any(row in rows for _, rows in results):
                limits[row] = (measured_limit(results, row, st.is_stable_spring(solver, mass_ratio))
                               if bisect else (None, None))
        add_map(out, table, solver[0], results, limits=limits, theory=theory_limits(solver[0], "spring"))
    return written(out, table, "spring", ("solver", "k dt^2/mu", "row", "outcome", "message"), draw_spring,
                   figures)


def draw_spring(out):
    rows = []
    for name, d in out.items():
        names = sorted({row for _, rs in d["results"] for row in rs}, reverse=True)
        rows += [f"{name}: {row}" for row in names]
    plots.stability_map(os.path.join(OUT, "stability-spring.png"),
                        "spring: outcome against k dt^2/mu (dt = 0.01 s)", "k dt^2 / mu", rows[::-1],
                        labelled_points(out))


def damper_maps(solvers=st.SOLVERS, grid=DAMPER_GRID, figures=True, bisect=True):
    out, table = {}, []
    for solver in solvers:
        results = [(r, {f"m2/m1 = {m:g}": st.two_body("damper", solver, r, m) for m in (1e-3, 1.0, 1e3)})
                   for r in grid]
        lim = (measured_limit(results, "m2/m1 = 1", st.is_stable_damper(solver))
               if bisect else (None, None))
        add_map(out, table, solver[0], results, limit=lim, theory=theory_limits(solver[0], "damper"))
    return written(out, table, "damper", ("solver", "c dt/mu", "row", "outcome", "message"), draw_damper,
                   figures)


def draw_damper(out):
    rows = [f"{name}: m2/m1 = {m:g}" for name in out for m in (1e3, 1.0, 1e-3)]
    plots.stability_map(os.path.join(OUT, "stability-damper.png"),
                        "damper: outcome against c dt/mu (dt = 0.01 s, 200 steps)", "c dt / mu", rows[::-1],
                        labelled_points(out))


HINGE_SOLVERS = (("symplectic", 1), ("Newmark", 3), ("implicitNewmark", 1))


def hinge_maps(grid=HINGE_GRID, figures=True, bisect=True, inertia_ratios=INERTIA_RATIOS):
    out, table = {}, []
    for solver, n_iter in HINGE_SOLVERS:
        name = f"{solver} x{n_iter}" if solver == "Newmark" else solver
        results = until_unstable(
            grid, lambda r: {f"J = {j:.2g}": hinge.rod_stability(solver, n_iter, r, j) for j in inertia_ratios},
            solver == "implicitNewmark")
        row = f"J = {1 / 3:.2g}"
        lim = (measured_limit(results, row, lambda r: hinge.rod_stability(solver, n_iter, r, 1 / 3)[0] == "stable")
               if bisect and row in results[0][1] else (None, None))
        add_map(out, table, name, results, limit=lim)
    return written(out, table, "hinge", ("solver", "k dt^2/m_eff", "row", "outcome", "message"), draw_hinge,
                   figures)


def draw_hinge(out):
    labels = [f"{n}: J = {j:.2g}" for n in out for j in sorted(INERTIA_RATIOS, reverse=True)]
    plots.stability_map(os.path.join(OUT, "stability-hinge.png"),
                        "hinge (rod on the world): outcome against k dt^2/m_eff (dt = 1 ms, 1 s)",
                        "k dt^2 / m_eff", labels[::-1], labelled_points(out))


def catenary_maps(grid=SPRING_GRID, figures=True, bisect=True):
    out, table = {}, []
    for solver, n_iter in (("symplectic", 1), ("Newmark", 1), ("Newmark", 3), ("implicitNewmark", 1)):
        name = f"{solver} x{n_iter}" if solver == "Newmark" else solver
        results = until_unstable(grid, lambda r: {"tension leg": cat.tension_leg_stability(solver, n_iter, r)},
                                 solver == "implicitNewmark")
        lim = (measured_limit(results, "tension leg",
                              lambda r: cat.tension_leg_stability(solver, n_iter, r)[0] == "stable")
               if bisect else (None, None))
        add_map(out, table, name, results, limit=lim)
    # (one row a solver: no row column)
    table = [(n, r, o, m) for n, r, _, o, m in table]
    return written(out, table, "catenary", ("solver", "EA dt^2/(L m)", "outcome", "message"), draw_catenary,
                   figures)


def draw_catenary(out):
    points = [(x, name, o) for name, d in out.items() for x, _, o in map_points(d["results"])]
    plots.stability_map(os.path.join(OUT, "stability-catenary.png"),
                        "catenary tension leg: outcome against EA dt^2/(L m) (dt = 0.01 s)",
                        "EA dt^2 / (L m)", list(out)[::-1], points)

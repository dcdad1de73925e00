"""The studies of the verification report: each runs its cases, writes its
CSV file and figures into docs/verification/, and returns what the
report's tables need."""
import math
import os

import catenary as cat
import hinge
import oscillator as osc
import plots
from vcommon import TOP, order, write_csv

OUT = os.path.join(TOP, "docs", "verification")
STEPS_PER_UNIT = (8, 16, 32, 64, 128, 256, 512)
ORDER_POINTS = 4          # finest points of a curve used for its order
SPRING_GRID = [10 ** (e / 2) for e in range(-8, 13)]     # 1e-4 .. 1e6
DAMPER_GRID = [10 ** (e / 4) for e in range(-4, 13)]     # 0.1 .. 1e3
HINGE_GRID = [10 ** (e / 2) for e in range(-4, 9)]       # 1e-2 .. 1e4
INERTIA_RATIOS = (0.1, 1 / 3, 10.0)


def cost_fit(rows):
    """CPU seconds per step and start-up, least squares of CPU against steps."""
    n = len(rows)
    mx = sum(r["steps"] for r in rows) / n
    my = sum(r["cpu"] for r in rows) / n
    sxx = sum((r["steps"] - mx) ** 2 for r in rows)
    slope = sum((r["steps"] - mx) * (r["cpu"] - my) for r in rows) / sxx
    return slope, my - slope * mx


def curve_order(rows, x="dt", y="error"):
    good = [r for r in rows if math.isfinite(r[y]) and r[y] < 0.5]
    good = sorted(good, key=lambda r: r[x])[:ORDER_POINTS]
    return order([r[x] for r in good], [r[y] for r in good]) if len(good) >= 2 else float("nan")


def oscillators(steps=STEPS_PER_UNIT, schemes=osc.SCHEMES, connectors=("spring", "spring-damper", "damper"),
                figures=True):
    """{connector: {scheme: {'rows', 'order', 'per_step', 'startup'}}}"""
    result, csv_rows = {}, []
    for connector in connectors:
        result[connector] = {}
        for scheme in schemes:
            rows = [dict(zip(("n", "dt", "steps", "cpu", "error"), r))
                    for r in osc.work_precision(connector, scheme, steps)]
            per_step, startup = cost_fit(rows)
            for r in rows:
                r["cpu_steps"] = per_step * r["steps"]
                csv_rows.append((connector, scheme[0], r["n"], r["dt"], r["steps"], r["cpu"],
                                 r["cpu_steps"], r["error"]))
            result[connector][scheme[0]] = {"rows": rows, "order": curve_order(rows),
                                            "per_step": per_step, "startup": startup}
        if figures:
            plots.loglog(os.path.join(OUT, f"work-precision-{connector}.png"),
                         f"{connector}: error against CPU time (10 periods)" if connector != "damper"
                         else "damper: error against CPU time (10 time constants)",
                         "CPU time of the steps [s]", "max error / scale",
                         [(name, [(r["cpu_steps"], r["error"]) for r in d["rows"]])
                          for name, d in result[connector].items()])
    if figures:
        write_csv(os.path.join(OUT, "oscillators.csv"),
                  ("connector", "scheme", "steps per unit", "dt", "steps", "CPU total", "CPU steps", "error"),
                  csv_rows)
    return result


def hinge_study(stiffnesses=(1e4, 1e5, 1e6), steps=(1e-4, 2e-4, 4e-4, 8e-4, 1.6e-3, 3.2e-3),
                solvers=(("symplectic", 1), ("implicitNewmark", 1)), figures=True):
    ref = hinge.reference()
    rows = []
    for solver, n_iter in solvers:
        for k in stiffnesses:
            for dt in steps:
                out, err = hinge.pendulum_error(ref, solver, n_iter, k, dt)
                rows.append({"solver": solver, "k": k, "dt": dt, "cpu": out.cpu, "error": err,
                             "status": out.status, "message": out.message,
                             "ratio": k * dt**2 / test_hinge_m_eff()})
    if figures:
        write_csv(os.path.join(OUT, "hinge.csv"),
                  ("solver", "k", "dt", "k dt^2/m_eff", "CPU", "error", "status", "message"),
                  [(r["solver"], r["k"], r["dt"], r["ratio"], r["cpu"], r["error"], r["status"],
                    r["message"]) for r in rows])
        plots.loglog(os.path.join(OUT, "work-precision-hinge.png"),
                     "hinge double pendulum: error against CPU time (0.5 s)",
                     "CPU time [s]", "max |c - c_exact| [m]",
                     [(f"{s} k={k:g}", [(r["cpu"], r["error"]) for r in rows
                                        if r["solver"] == s and r["k"] == k and r["status"] == "ok"])
                      for s, _ in solvers for k in stiffnesses])
    finest = min(steps)
    orders_k = {}
    for s, _ in solvers:
        pts = [r for r in rows if r["solver"] == s and r["dt"] == finest and r["status"] == "ok"]
        orders_k[s] = order([1 / r["k"] for r in pts], [r["error"] for r in pts])
    return {"rows": rows, "order_k": orders_k}


def test_hinge_m_eff():
    return hinge.test_hinge.M_EFF


def catenary_study(figures=True, divisions=(25, 50, 100, 200, 400), ref_division=1600):
    qs = cat.quasi_static()
    cost_line = cat.cost_per_call("catenary", cat.MOORING,
                                  lambda s: (cat.XA + 5 * math.sin(2 * math.pi * s), 0, cat.ZA))
    cost_spring = cat.cost_per_call("linearSpring", {"stiffness": 100.0, "restLength": 1.0,
                                                     "B.p[1]": 0.0, "B.p[2]": 0.0, "B.p[3]": 0.0},
                                    lambda s: (1 + 0.1 * math.sin(2 * math.pi * s), 0, 0))
    period = cat.surge_period()
    end = 2 * period
    out, t_ref, x_ref = cat.moored("implicitNewmark", 1, period / ref_division, end)
    if not out.ok:
        raise RuntimeError(f"moored reference failed: {out.message}")
    ref = dict(zip((round(t / (period / ref_division)) for t in t_ref), x_ref))
    dyn = []
    for solver, n_iter in (("symplectic", 1), ("Newmark", 3), ("implicitNewmark", 1)):
        for n in divisions:
            dt = period / n
            out, t, x = cat.moored(solver, n_iter, dt, end)
            stride = ref_division // n
            err = (max(abs(xi - ref[round(ti / dt) * stride]) for ti, xi in zip(t, x)) / cat.OFFSET
                   if out.ok else float("inf"))
            dyn.append({"solver": f"{solver} x{n_iter}" if solver == "Newmark" else solver, "n": n,
                        "dt": dt, "cpu": out.cpu, "cpu_per_s": out.cpu / end, "error": err})
    orders = {s: curve_order([r for r in dyn if r["solver"] == s]) for s in {r["solver"] for r in dyn}}
    if figures:
        write_csv(os.path.join(OUT, "catenary-quasi-static.csv"),
                  ("case", "x", "z", "H", "V", "error", "message"), qs)
        write_csv(os.path.join(OUT, "catenary-moored.csv"),
                  ("solver", "steps per period", "dt", "CPU", "CPU per simulated s", "error"),
                  [(r["solver"], r["n"], r["dt"], r["cpu"], r["cpu_per_s"], r["error"]) for r in dyn])
        plots.loglog(os.path.join(OUT, "work-precision-catenary.png"),
                     "body moored by two catenary FMUs: error against CPU time (2 surge periods)",
                     "CPU time [s]", "max |x - x_ref| / offset",
                     [(s, [(r["cpu"], r["error"]) for r in dyn if r["solver"] == s]) for s in sorted(orders)])
    return {"quasi_static": qs, "cost_line": cost_line, "cost_spring": cost_spring,
            "period": period, "dynamic": dyn, "orders": orders}

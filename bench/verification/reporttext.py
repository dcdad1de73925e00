"""The sections of docs/verification.md."""
import math
import os

import catenary as cat
import hinge
import oscillator as osc
from stabsection import failure_kinds, nan_count
from vcommon import TOP

FIG = "verification"


def sections(r, measured, table, g, limit_text):
    s = intro()
    s += oscillator_section(r["oscillators"], table, g)
    s += hinge_section(r["hinge"], table, g)
    s += catenary_section(r["catenary"], table, g)
    s += stability_section(r, table, g, limit_text)
    s += extremes_section(r["extremes"], table)
    s += practical_section(r, g)
    if os.path.isfile(os.path.join(TOP, "docs", "floating-stability.md")):
        s += ("\n## Floating bodies in a fluid\n\nThe stability of the fluid-body coupling (outer "
              "correctors per step and cost against body density) is in "
              "[floating-stability.md](floating-stability.md).\n")
    return s


def intro():
    return (
        "Solvers: OpenFOAM v1912's `symplectic` and `Newmark` (x1, x3: solves per time step, the "
        "PIMPLE outer correctors of a CFD run) and the project's `implicitNewmark` (trapezoidal, "
        "[implicit-rigid-body-solver.md](implicit-rigid-body-solver.md)) in `rigidBodySim`; "
        "`fmusim twobody` explicit (symplectic Euler) and implicit (trapezoidal, iterated coupling) "
        "([fmusim.md](fmusim.md)). The connectors are the FMUs of `build/fmus/`: linearSpring, "
        "linearDamper, hinge, catenary (quasi-static). The dynamic lumped-mass line (`mooringLine.fmu`: "
        "segments N, CVODE tolerances, step) is not covered by this report.\n\n")


def oscillator_section(res, table, g):
    s = ("## Spring and damper: error against CPU time\n\n"
         f"Two bodies, {osc.M1:g} kg and {osc.M2:g} kg, joined at their centres (prismatic joints in "
         "`rigidBodySim`, free bodies in `fmusim`), against the analytic two-body solution "
         f"(`bench/verification/oscillator.py`): spring k = {osc.K:g} N/m, omega = sqrt(k (1/m1 + 1/m2)) = "
         f"{osc.OMEGA:.4g} rad/s, released {osc.S0:g} m from rest length, 10 periods; spring-damper: "
         f"the same with damping ratio {osc.ZETA:g}; damper (linearDamper alone): relative velocity "
         f"{osc.U0:g} m/s decaying with time constant mu/c = {osc.TAU:g} s, 10 time constants. Error: largest "
         "|s - s_exact| of the extension s over the run, relative to the initial extension (spring) or "
         "the total travel (damper). CPU time of the steps: the run's CPU time less the start-up, "
         "from a least-squares fit of CPU time against steps over the scheme's runs (start-up and cost "
         "per step in the last table). Observed order: slope of log(error) against log(dt) over the "
         f"finest points with error below 0.5.\n\n")
    for connector, schemes in res.items():
        unit = "steps per period" if connector != "damper" else "steps per time constant"
        s += f"### {connector}\n\n![{connector}]({FIG}/work-precision-{connector}.png)\n\n"
        ns = [row["n"] for row in next(iter(schemes.values()))["rows"]]
        header = ["scheme"] + [f"{n}" for n in ns] + ["order"]
        rows = [[name] + [g(row["error"], 2) for row in d["rows"]] + [f"{d['order']:.2f}"]
                for name, d in schemes.items()]
        s += f"Error at {unit}:\n\n" + table(header, rows) + "\n"
    any_res = res[next(iter(res))]
    s += ("Cost (spring runs): CPU time per step and start-up of each program, and the CPU time "
          "to reach an error of 1e-2 on the spring (interpolated on the curve, 10 periods):\n\n")
    rows = []
    for name, d in any_res.items():
        rows.append((name, f"{d['per_step'] * 1e6:.0f} us", f"{d['startup'] * 1e3:.0f} ms",
                     g(cost_at(d["rows"], 1e-2), 2) + " s"))
    s += table(("scheme", "CPU per step", "start-up", "CPU for error 1e-2"), rows)
    s += ("\nOpenFOAM's `symplectic` and `Newmark` solvers start from a stored acceleration of zero, "
          "which costs an O(dt) amplitude error for the whole run: they are first order in this "
          "measure, though `symplectic` is second order in the period "
          "(tests/bridge/test_two_bodies.py). `implicitNewmark` computes the initial acceleration and "
          "stays second order; `fmusim explicit` is symplectic Euler, first order.\n\n")
    return s


def cost_at(rows, target):
    pts = sorted((r["error"], r["cpu_steps"]) for r in rows if math.isfinite(r["error"]) and r["error"] > 0)
    for (e1, c1), (e2, c2) in zip(pts, pts[1:]):
        if e1 <= target <= e2:
            w = math.log(target / e1) / math.log(e2 / e1)
            return math.exp(math.log(c1) + w * (math.log(c2) - math.log(c1)))
    return None


def hinge_section(h, table, g):
    s = ("## Hinge: error against CPU time\n\n"
         "The double pendulum of `tests/bridge/test_hinge.py` (two 2 kg rods of 0.5 m on two hinge FMUs, "
         "free bodies, gravity tilted 0.5 rad, penalty damping 0.1 of critical) against the same "
         "pendulum on OpenFOAM's exact revolute (Ry) joints, computed by implicitNewmark at dt = "
         f"{hinge.DT_REF:g} s; error: largest distance of the rods' centres from the exact ones over "
         f"{hinge.END:g} s. The penalty lets the hinge points part by load/k, so the error has a floor "
         "of order 1/k; the step adds the scheme's error or, beyond the stability limit, ends the run.\n\n"
         f"![hinge]({FIG}/work-precision-hinge.png)\n\n")
    steps = sorted({r["dt"] for r in h["rows"]})
    header = ["solver", "k [N/m]"] + [f"dt {dt:g}" for dt in steps]
    rows = []
    for solver in dict.fromkeys(r["solver"] for r in h["rows"]):
        for k in sorted({r["k"] for r in h["rows"]}):
            cells = []
            for dt in steps:
                r = next(x for x in h["rows"] if x["solver"] == solver and x["k"] == k and x["dt"] == dt)
                cells.append(f"{g(r['error'], 2)} m, {r['cpu']:.2f} s" if r["status"] == "ok" else "failed")
            rows.append([solver, f"{k:g}"] + cells)
    s += "Error and CPU time:\n\n" + table(header, rows)
    s += ("\nObserved order in 1/k at the smallest step: " +
          ", ".join(f"{name} {p:.2f}" for name, p in h["order_k"].items()) + ". Failed runs: " +
          "; ".join(sorted({f"{r['solver']} k {r['k']:g} dt {r['dt']:g} (k dt^2/m_eff = {r['ratio']:.3g}): "
                            f"{r['message'][:90]}" for r in h["rows"] if r["status"] != "ok"})[:3]) + ".\n\n")
    return s


def catenary_section(c, table, g):
    s = ("## Catenary\n\n### Quasi-static line against the closed-form catenary\n\n"
         f"Line L = {cat.L:g} m, EA = {cat.EA:g} N, w = {cat.W:g} N/m unless stated. For chosen fairlead "
         "tensions H, V the spans follow in closed form (`catenary.py`, the relations of "
         "connectors/catenary/README.md); the fairlead is put there and the FMU (`fmusim run`) must "
         "return H and V. Error: max(|dH|, |dV|) / sqrt(H^2 + V^2).\n\n")
    rows = [(case, g(x, 5), g(z, 5), g(h, 4), g(v, 4), g(err, 2) if not msg else msg)
            for case, x, z, h, v, err, msg in c["quasi_static"]]
    s += table(("case", "x [m]", "z [m]", "H [N]", "V [N]", "error"), rows)
    s += (f"\nCost of one `fmi2DoStep` (fmusim run, fairlead moving 5 m, warm start; CPU, fmusim's "
          f"start-up removed): catenary {c['cost_line'] * 1e6:.1f} us, linearSpring "
          f"{c['cost_spring'] * 1e6:.1f} us.\n\n")
    s += ("### Moored body\n\n"
          f"A {cat.MB:g} kg body on a prismatic x joint between two lines to anchors at "
          f"(+-{cat.XA:g}, 0, -{cat.ZA:g}) m, released {cat.OFFSET:g} m off centre; surge period "
          f"{c['period']:.3g} s (from the FMU's stiffness at the centre), 2 periods, against implicitNewmark "
          "at 1600 steps per period.\n\n"
          f"![catenary]({FIG}/work-precision-catenary.png)\n\n")
    ns = sorted({r["n"] for r in c["dynamic"]})
    rows = []
    for solver in sorted(c["orders"]):
        pts = {r["n"]: r for r in c["dynamic"] if r["solver"] == solver}
        rows.append([solver] + [g(pts[n]["error"], 2) for n in ns] + [f"{c['orders'][solver]:.2f}",
                    f"{pts[ns[-1]]['cpu_per_s'] * 1e3:.2f} ms"])
    s += table(["solver"] + [f"{n}/period" for n in ns] + ["order", f"CPU per simulated s at {ns[-1]}/period"],
               rows) + "\n"
    return s


def stability_section(r, table, g, limit_text):
    from stabsection import stability_text
    return stability_text(r, table, g, limit_text)


def extremes_section(rows, table):
    s = ("## Extreme cases\n\nEach case must give a correct result (against its exact answer, bound "
         "in the detail) or stop with a clear error; a non-finite number in any output counts as NaN.\n\n")
    s += table(("case", "connector", "tool", "outcome", "detail"),
               rows)
    n_nan = sum(1 for row in rows if row[3] in ("NaN", "wrong"))
    s += f"\nCases with a NaN or a wrong result: {n_nan}.\n\n"
    return s


def practical_section(r, g):
    h = r["hinge"]["rows"]
    bad = [x for x in h if x["solver"] == "symplectic" and x["status"] != "ok"]
    good = [x for x in h if x["solver"] == "implicitNewmark" and x["status"] == "ok"]
    s = "## Practical consequences\n\n"
    if bad:
        worst = min(bad, key=lambda x: (-x["k"], x["dt"]))
        imp = next((x for x in good if x["k"] == worst["k"] and x["dt"] == worst["dt"]), None)
        s += (f"- A hinge stiff enough to be accurate is unstable at CFD time steps with OpenFOAM's solvers: "
              f"k = {worst['k']:g} N/m (gap about load/k) at dt = {worst['dt']:g} s, k dt^2/m_eff = "
              f"{worst['ratio']:.3g}, stops the symplectic run"
              + (f", while implicitNewmark runs it with an error of {g(imp['error'], 2)} m "
                 f"in {imp['cpu']:.2f} s CPU" if imp else "") +
              ". Remedy: `implicitNewmark` ([implicit-rigid-body-solver.md](implicit-rigid-body-solver.md)).\n")
    newmark = r["spring_map"].get("Newmark x1", {}).get("limits", {}).get("FMU to world")
    if newmark:
        s += (f"- OpenFOAM's Newmark evaluates the restraints at the previous iterate: its step grows every "
              f"oscillation (theory: growth above 1e-9 per step at every k dt^2/m), and with one solve per "
              f"step the spring stays within 2x over 50 periods only up to k dt^2/m = {g(newmark[0])}; "
              f"3 outer correctors raise that to "
              f"{g(r['spring_map']['Newmark x3']['limits']['FMU to world'][0])}. A stiff connector needs "
              "`symplectic` within its limit or `implicitNewmark`.\n")
    fpe, named = failure_kinds(r)
    s += (f"- Of the failed runs of the stability maps, {fpe} were stopped by OpenFOAM's floating-point "
          f"trap (SIGFPE) in its own arithmetic, {named} by a named error (the FMU refusing non-finite "
          f"inputs or outputs, fmusim's checks); runs with a non-finite number in their output: "
          f"{nan_count(r)}.\n")
    return s

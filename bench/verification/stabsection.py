"""The stability section of docs/verification.md."""
import stability as st

FIG = "verification"


def nan_count(r):
    n = 0
    for key in ("spring_map", "damper_map", "hinge_map", "catenary_map"):
        for d in r[key].values():
            n += sum(1 for _, rows in d["results"] for o, _ in rows.values() if o == "nan")
    return n


def disagreements(spring_map):
    """Points where the built-in and FMU rows, or the mass-ratio rows,
    have different outcomes: 'solver at ratio' strings."""
    builtin, ratios = [], []
    for name, d in spring_map.items():
        for x, rows in d["results"]:
            outcomes = {row: o for row, (o, _) in rows.items()}
            if "built-in to world" in outcomes and outcomes["built-in to world"] != outcomes["FMU to world"]:
                builtin.append(f"{name} at {x:.3g}")
            if len({o for row, o in outcomes.items() if row.startswith("two bodies")}) > 1:
                ratios.append(f"{name} at {x:.3g}")
    return ", ".join(builtin), ", ".join(ratios)


def failure_kinds(r):
    """Failed runs of the maps: (trapped by OpenFOAM's SIGFPE, stopped
    with a named error)."""
    fpe = named = 0
    for key in ("spring_map", "damper_map", "hinge_map", "catenary_map"):
        for d in r[key].values():
            for _, rows in d["results"]:
                for o, m in rows.values():
                    if o == "failed":
                        fpe, named = (fpe + 1, named) if "SIGFPE" in m else (fpe, named + 1)
    return fpe, named


def first_failure(d, g):
    """The first failure message of a solver's map and the ratio it shows
    from, or '-'."""
    return "; ".join(f"{m[:110]} (from {g(x)})" for x, m in list(d["messages"].values())[:1]) or "-"


def limit_table(section, figure, solvers, limit, table, g, limit_text):
    """A map's section text, its figure and the table of each solver's
    limit (header limit) and first failure."""
    return (section + f"![{figure} stability]({FIG}/stability-{figure}.png)\n\n"
            + table(("solver", limit, "failure message"),
                    [(name, limit_text(d["limit"]), first_failure(d, g)) for name, d in solvers.items()]))


def stability_text(r, table, g, limit_text):
    s = ("## Stability on stiff cases\n\n"
         f"A run is stable when the largest displacement from equilibrium (spring, hinge gap, tension "
         f"leg) or relative velocity (damper) stays within {st.GROWTH:g} times its initial value "
         "(hinge: gap below 10 times the static gap m g/k) over 50 periods (at least 200, at most 5000 steps; "
         "damper: 200 steps; hinge: 1000 steps); unstable when it runs but grows beyond; failed when "
         "the program stops with an error. The limit is bisected to 2 % between the last stable and the "
         "first unstable point of the grid. Theory: the solver's own recurrence on x'' = -(k/m) x "
         "(`theory.py`, written from OpenFOAM's solver source) under the same criterion, and its "
         "asymptotic limit (spectral radius of the step at most 1): symplectic/Verlet 4 (the 2x criterion "
         "gives 3: the discrete orbit's amplitude in x is 1/sqrt(1 - k dt^2/4m) times the initial one), "
         "lagged Newmark none (unstable at every step), trapezoidal unconditional.\n\n")
    s += ("### Spring\n\nRows: OpenFOAM's built-in `linearSpring` and the linearSpring FMU holding a "
          "1 kg body to the world (one run, side by side), and two bodies joined by the FMU with mass "
          "ratios 1e-3, 1 and 1e3 (mu the reduced mass); dt = 0.01 s, k varied. An explicit solver's sweep "
          "stops after two points with no stable row.\n\n"
          f"![spring stability]({FIG}/stability-spring.png)\n\n")
    rows = []
    for name, d in r["spring_map"].items():
        lw = d["limits"].get("FMU to world")
        lt = d["limits"].get("two bodies m2/m1 = 1")
        rows.append((name, limit_text(lw) if lw else "-", limit_text(lt) if lt else "-",
                     g(d["theory"][0]), g(d["theory"][1]) if d["theory"][1] > 0 else "none (unstable)",
                     first_failure(d, g)))
    s += table(("solver", "limit k dt^2/m, to world", "limit k dt^2/mu, two bodies", "theory (2x criterion)",
                "theory (growth < 1e-9 per step)", "failure message"), rows)
    builtin, ratios = disagreements(r["spring_map"])
    s += ("\nPoints of the map where the built-in linearSpring and the FMU to the world differ: "
          f"{builtin or 'none'}; where the two-body rows of different mass ratios differ: {ratios or 'none'} "
          "(the mass ratio enters only through the reduced mass). "
          f"At dt = 0.001 s symplectic's two-body limit is {limit_text(r['spring_dt'])}, against "
          f"{limit_text(r['spring_map']['symplectic']['limits']['two bodies m2/m1 = 1'])} at dt = 0.01 s: "
          "dt and k enter only as k dt^2/mu.\n")
    fi = r["spring_map"].get("fmusim implicit", {}).get("limits", {}).get("two bodies m2/m1 = 1")
    if fi and fi[1] is not None:
        s += (f"\n`fmusim implicit` is not unconditionally stable although the trapezoidal rule is: beyond "
              f"k dt^2/mu = {g(fi[0])} its fixed-point coupling iterations stop at their tolerance (relative to "
              "the largest loads so far) on a growing solution. Use it below that limit, or use "
              "`implicitNewmark`, whose Newton iterations hold to 1e6.\n")
    s += "\n"
    s += ("### Damper\n\nTwo bodies joined by the linearDamper FMU, mass ratios 1e-3, 1, 1e3, dt = 0.01 s, "
          "c varied.\n\n"
          f"![damper stability]({FIG}/stability-damper.png)\n\n")
    rows = [(name, limit_text(d["limit"]), g(d["theory"][0]), g(d["theory"][1]) if d["theory"][1] > 0 else "none")
            for name, d in r["damper_map"].items()]
    s += table(("solver", "limit c dt/mu", "theory (2x criterion)", "theory (growth < 1e-9 per step)"), rows)
    s += limit_table("\n### Hinge\n\nOne rod (2 kg, centre 0.25 m below the hinge point) hanging from the "
                     "world on a hinge FMU, no penalty damping, rotational penalty k d^2; J = I/(m d^2) the "
                     "inertia ratio (1/3: a uniform rod), m_eff = m J/(1 + J) the mass felt across the rod at "
                     "the hinge point.\n\n", "hinge", r["hinge_map"], "limit k dt^2/m_eff (J = 1/3)",
                     table, g, limit_text)
    s += limit_table("\n### Catenary\n\nA tension leg: a 1 kg body on a prismatic z joint held down by a "
                     "vertical weightless line (catenary FMU, vertical regime, stiffness EA/L) against a lift "
                     "that keeps the line taut; dt = 0.01 s, EA varied.\n\n", "catenary", r["catenary_map"],
                     "limit EA dt^2/(L m)", table, g, limit_text)
    s += f"\nRuns of the maps with a non-finite number in their output: {nan_count(r)}.\n\n"
    return s

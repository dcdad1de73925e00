"""A fast subset of the verification report (docs/verification.md): the
observed orders of convergence and the stability limits, measured as the
report measures them (bench/verification, a few points per curve), checked
against the documented values and bands of
bench/verification/documented.csv, which the report prints too.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench", "verification"))
import catenary as cat  # noqa: E402
import hinge  # noqa: E402
import oscillator as osc  # noqa: E402
import stability as st  # noqa: E402
import studies  # noqa: E402
from vcommon import bisect_limit, order, read_documented  # noqa: E402

DOC = read_documented()
SCHEMES = {s[0]: s for s in osc.SCHEMES}
SOLVERS = {s[0]: s for s in st.SOLVERS}
failures = passes = 0


def check(quantity, measured, detail=""):
    """The measured value within the documented band (the band's reason is
    in documented.csv, next to the value)."""
    global failures, passes
    value, low, high, reason = DOC[quantity]
    ok = measured is not None and math.isfinite(measured) and low <= measured <= high
    print(f"{'PASS' if ok else 'FAIL'} {quantity}: measured {measured:.4g}, documented {value:g} "
          f"in [{low:g}, {high:g}] ({reason}){detail}")
    passes, failures = passes + ok, failures + (not ok)


def limit(quantity, stable):
    """Bisect the limit inside 1.25x of the documented value; the bracket
    itself must hold (stable below, not stable above), else the limit has
    moved and the measurement is that end of the bracket."""
    value = DOC[quantity][0]
    low, high = value / 1.25, value * 1.25
    if not stable(low):
        return low / 1.25
    if stable(high):
        return high * 1.25
    return bisect_limit(stable, low, high)[0]


def main():
    global failures, passes
    # Orders: the finest three points of the report's curves (10 periods
    # or time constants, 128 to 512 steps each).
    for connector, names in (("spring", ("symplectic", "implicitNewmark", "fmusim explicit", "fmusim implicit")),
                             ("damper", ("symplectic", "implicitNewmark"))):
        for name in names:
            rows = [dict(zip(("n", "dt", "steps", "cpu", "error"), r))
                    for r in osc.work_precision(connector, SCHEMES[name], (128, 256, 512))]
            errors = ", ".join(f"{r['error']:.2e}" for r in rows)
            check(f"order {connector} {name}", studies.curve_order(rows), f"; errors {errors}")

    # Hinge: first order in 1/k; implicitNewmark at a step where the
    # penalty error dominates (the report's table: flat in dt).
    ref = hinge.reference()
    errors = [hinge.pendulum_error(ref, "implicitNewmark", 1, k, 8e-4)[1] for k in (1e4, 1e5, 1e6)]
    shown = ", ".join(f"{e:.2e}" for e in errors)
    check("order hinge 1/k implicitNewmark", order([1e-4, 1e-5, 1e-6], errors), f"; errors {shown} m")

    # Catenary moored body: implicitNewmark, 100 to 400 steps per period.
    r = studies.catenary_study(figures=False, divisions=(100, 200, 400))
    check("order catenary moored implicitNewmark", r["orders"]["implicitNewmark"])

    # Stability limits.
    sym = SOLVERS["symplectic"]
    check("limit spring FMU to world symplectic",
          limit("limit spring FMU to world symplectic", st.is_stable_spring(sym, None)))
    check("limit spring FMU to world Newmark x3",
          limit("limit spring FMU to world Newmark x3", st.is_stable_spring(SOLVERS["Newmark x3"], None)))
    check("limit spring two bodies m2/m1 = 1 fmusim implicit",
          limit("limit spring two bodies m2/m1 = 1 fmusim implicit",
                st.is_stable_spring(SOLVERS["fmusim implicit"], 1.0)))
    check("limit damper symplectic", limit("limit damper symplectic", st.is_stable_damper(sym)))
    check("limit hinge symplectic",
          limit("limit hinge symplectic", lambda x: hinge.rod_stability("symplectic", 1, x, 1 / 3)[0] == "stable"))
    check("limit catenary symplectic",
          limit("limit catenary symplectic", lambda x: cat.tension_leg_stability("symplectic", 1, x)[0] == "stable"))

    # implicitNewmark has no limit: stable at k dt^2/m = 1e4, where every
    # built-in solver has long diverged (the report's map runs to 1e6).
    outcome = st.world_spring(SOLVERS["implicitNewmark"], 1e4)
    ok = all(o == "stable" for o, _ in outcome.values())
    print(f"{'PASS' if ok else 'FAIL'} implicitNewmark stable at k dt^2/m = 1e4: {outcome}")
    passes, failures = passes + ok, failures + (not ok)

    print(f"{passes} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

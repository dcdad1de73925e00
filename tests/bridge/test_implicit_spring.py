"""The implicitNewmark rigid-body solver on the single-body spring, from
soft to very stiff, side by side with OpenFOAM's own solvers.

A body of mass m on a prismatic joint hangs from a spring (no gravity, no
damping) and starts at rest X0 from equilibrium. Two identical, independent
bodies share the model: one on the built-in linearSpring, one on the
linearSpring FMU. For k dt^2/m from 1e-4 to 1e6, over 50 periods (at least
200 steps):

- implicitNewmark (default rhoInf 1, the trapezoidal rule) must follow the
  trapezoidal rule's exact discrete solution: amplitude X0 conserved, phase
  advance 2 atan(omega dt / 2) per step (period error (omega dt)^2/12 to
  leading order), on both bodies, with 1 and 3 solves per step;
- symplectic (1 solve) and Newmark (3 solves, as the floatingObject
  tutorial) run on the same model: they must be stable at 1e-4 (so the
  comparison is fair) and diverge from 100 on;
- with rhoInf 0.5 the stiff mode (omega dt = 1000) is damped away and the
  soft one (omega dt = 0.01) is not.
"""
import math
import sys

from foamfmi.bridgecase import check, summary
from foamfmi.implicitcase import (
    MASS, X0, growth, run_bodies, solver_entry, spring_errors, spring_model,
)

DT = 0.01
RATIOS = (1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6)  # k dt^2 / m


def steps(omega):
    return max(200, math.ceil(50 * 2 * math.pi / (omega * DT)))


def main():
    failures = checks = 0
    print(f"{'k dt^2/m':>9} {'implicit amp':>13} {'implicit phase':>15} "
          f"{'symplectic':>11} {'Newmark x3':>11}  (growth: max|x|/X0)")
    for ratio in RATIOS:
        k = ratio * MASS / DT**2
        omega = math.sqrt(k / MASS)
        n = steps(omega)

        for n_iter in (1, 3):
            b, log = run_bodies(
                f"implicitSpring.{ratio:g}.{n_iter}",
                spring_model(solver_entry("implicitNewmark"), k), n * DT, DT, n_iter,
            )
            if b is None:
                checks += 1
                failures += check(f"implicitNewmark k dt^2/m {ratio:g} nIter {n_iter}",
                                  False, log[-2000:])
                continue
            errors = {body: spring_errors(b, body, omega, DT) for body in ("builtin", "fmu")}
            # Newton stops at a residual of 1e-10 of the acceleration per
            # step; over up to 31416 steps the measured drift from the exact
            # discrete solution stays below 2e-10 of X0. 1e-8 leaves room for
            # round-off and is far below the error of any other method
            # (the trapezoidal phase error itself, against the exact
            # solution, is 2.6e-3 of X0 after 50 periods at 1e-4).
            worst = max(max(e) for e in errors.values())
            checks += 1
            failures += check(
                f"implicitNewmark k dt^2/m {ratio:g} nIter {n_iter}", worst < 1e-8,
                "amplitude/phase errors " + ", ".join(
                    f"{body} {a:.1e}/{p:.1e}" for body, (a, p) in errors.items()),
            )
            # The FMU and the built-in spring compute the same law
            diff = max(abs(x - y) for x, y in zip(b["builtin.c.z"], b["fmu.c.z"]))
            checks += 1
            failures += check(f"FMU = built-in, k dt^2/m {ratio:g} nIter {n_iter}",
                              diff <= 1e-10 * X0, f"max difference {diff:.1e} m")
            if n_iter == 1:
                implicit = errors["builtin"]

        # The built-in solvers on the same model (limited to 5000 steps:
        # a divergence shows long before)
        builtin = {}
        for solver, n_iter in (("symplectic", 1), ("Newmark", 3)):
            b, _ = run_bodies(f"builtinSpring.{solver}.{ratio:g}",
                              spring_model(solver_entry(solver), k),
                              min(n, 5000) * DT, DT, n_iter)
            builtin[solver] = math.inf if b is None else growth(b, "builtin")
            if ratio <= 1e-4:
                # Stable: amplitude within 1e-3 (their amplitude error at
                # omega dt = 0.01 is ~1e-5)
                ok = builtin[solver] < 1.001
            elif ratio >= 100:
                # Diverged: at least tenfold growth, or the run stopped
                ok = builtin[solver] > 10
            else:
                continue
            checks += 1
            failures += check(f"{solver} x{n_iter} {'stable' if ratio <= 1e-4 else 'diverges'}"
                              f" at k dt^2/m {ratio:g}", ok, f"growth {builtin[solver]:.3g}")
        print(f"{ratio:9.0e} {implicit[0]:13.1e} {implicit[1]:15.1e} "
              f"{builtin['symplectic']:11.3g} {builtin['Newmark']:11.3g}")

    # Numerical damping with rhoInf 0.5. The final amplitude
    # sqrt(x^2 + (v/omega)^2) of the stiff mode (omega dt = 1000) falls by
    # 0.5 per step: 0.5^40 = 1e-12 after 40 steps, 1e-6 allows for the
    # first steps' transient. The soft mode (omega dt = 0.01) loses
    # O((omega dt)^3) per step of amplitude: 1e-3 over 50 periods (31416
    # steps) is loose, yet the stiff mode's loss is nowhere near it.
    for ratio, n, limit, what in ((1e6, 40, (0, 1e-6), "stiff mode damped"),
                                  (1e-4, steps(0.01 / DT), (0.999, 1.0 + 1e-9), "soft mode kept")):
        k = ratio * MASS / DT**2
        omega = math.sqrt(k / MASS)
        b, log = run_bodies(f"implicitRho.{ratio:g}",
                            spring_model(solver_entry("implicitNewmark", rhoInf=0.5), k),
                            n * DT, DT)
        checks += 1
        if b is None:
            failures += check(f"rhoInf 0.5, k dt^2/m {ratio:g}", False, log[-2000:])
            continue
        amplitude = math.hypot(b["builtin.c.z"][-1] + X0, b["builtin.v.z"][-1] / omega) / X0
        failures += check(f"rhoInf 0.5, k dt^2/m {ratio:g}: {what}",
                          limit[0] <= amplitude <= limit[1],
                          f"final amplitude {amplitude:.3e} X0 after {n} steps")

    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())

"""implicitNewmark against OpenFOAM's built-in rigid-body solvers on the
single-body spring (python/foamfmi/implicitcase.py), side by side:

- cost: wall time per solve of rigidBodySim on the same model (built-in
  linearSpring and linearSpring FMU bodies), relative to Newmark with one
  solve per step, at k dt^2/m = 1e-2 (all solvers stable), 20000 steps;
- stability: the largest k dt^2/m of a sweep (factors of about 2) at which
  the displacement stays within 2 X0 (a diverging run grows without
  bound) over 50 periods (at least
  200 steps, at most 5000).

Run in the project's environment:
    tests/run-with-openfoam python3 bench/implicitSolver/run.py
"""
import math
import os
import sys
import time

from foamfmi.implicitcase import MASS, growth, run_bodies, solver_entry, spring_model

DT = 0.01
SOLVERS = (("symplectic", 1), ("Newmark", 1), ("Newmark", 3), ("CrankNicolson", 3),
           ("implicitNewmark", 1), ("implicitNewmark", 3))
SWEEP = [10 ** (e / 3) for e in range(-12, 19)]  # 1e-4 .. 1e6


def stable(solver, n_iter, ratio):
    k = ratio * MASS / DT**2
    n = min(5000, max(200, math.ceil(50 * 2 * math.pi / (math.sqrt(k / MASS) * DT))))
    b, _ = run_bodies("benchStability", spring_model(solver_entry(solver), k), n * DT, DT, n_iter)
    return b is not None and growth(b, "builtin") <= 2 and growth(b, "fmu") <= 2


def cost(solver, n_iter, steps=20000):
    k = 1e-2 * MASS / DT**2
    start = time.perf_counter()
    b, _ = run_bodies("benchCost", spring_model(solver_entry(solver), k), steps * DT, DT, n_iter)
    return (time.perf_counter() - start) / (steps * n_iter)


def main():
    base = cost("Newmark", 1)
    print(f"{'solver':>16} {'solves/step':>11} {'cost/solve':>11} {'vs Newmark':>10} "
          f"{'largest stable k dt^2/m':>24}")
    for solver, n_iter in SOLVERS:
        c = cost(solver, n_iter)
        largest = None
        for ratio in SWEEP:
            if stable(solver, n_iter, ratio):
                largest = ratio
            elif solver != "implicitNewmark":
                break
        shown = "none" if largest is None else f"{largest:.3g}"
        if largest == SWEEP[-1]:
            shown = f">= {shown} (sweep end)"
        print(f"{solver:>16} {n_iter:>11} {c * 1e6:9.1f} us {c / base:10.2f} {shown:>24}")
    print("cost/solve: wall time of rigidBodySim per solve, start-up and output included")
    return 0


if __name__ == "__main__":
    sys.exit(main())

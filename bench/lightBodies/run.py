#!/usr/bin/env python3
"""Light floating bodies: OpenFOAM's coupling against the added-mass coupling.

OpenFOAM's floatingObject tutorial (interFoam/RAS, the box in sway and
pitch) at several body densities, each run to the same end time with
interFoamAliasSafe:

  stock      rigidBodyMotion, Newmark, the tutorial's accelerationRelaxation
             0.7 and 3 outer correctors;
  hand       the same with the relaxation found by hand for a density
             (0.15 at 100 kg/m^3, docs/floating-stability.md);
  addedMass3 addedMassRigidBodyMotion, no relaxation, 3 outer correctors
             (the stock cost);
  addedMass  addedMassRigidBodyMotion, one dictionary for every density: no
             relaxation, at most 10 outer correctors, a step ends when the
             coupling residual is below the tolerance.

Prints the table of docs/floating-stability.md ("Added-mass coupling"): end
time reached, outer correctors per step, CPU per simulated second, and
where both ran the motion of the coupled run against the relaxed one.

    tests/run-with-openfoam bench/lightBodies/run.py [-end-time 1.5]
        [-densities 500,300,100,30,10] [-tolerance 1e-2] [-keep DIR]
"""

import argparse
import os
import shutil
import sys
import tempfile

from foamfmi import floatingobject as foc

HAND_RELAXATION = {100: 0.15, 300: 0.3}


def row(name, density, r, end_time):
    reached = f"{r['time']:.3g} s" + (" (End)" if r["ended"] else "")
    per_step = r["correctors"]/max(r["steps"], 1)
    cpu = f"{r['cpu']/r['time']:.1f} s" if r["ended"] else "-"
    return (f"| {density:>4} | {name:<34} | {reached:<12} | {r['steps']:>5} "
            f"| {per_step:>5.2f} | {cpu:>6} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-end-time", type=float, default=1.5)
    parser.add_argument("-densities", default="500,300,100,30,10")
    parser.add_argument("-tolerance", type=float, default=1e-2)
    parser.add_argument("-keep", help="keep the runs in this directory")
    args = parser.parse_args()

    work = args.keep or tempfile.mkdtemp(prefix="lightBodies.")
    os.makedirs(work, exist_ok=True)
    base = foc.mesh(os.path.join(work, "mesh"))
    densities = [int(d) for d in args.densities.split(",")]

    print(f"floatingObject tutorial to {args.end_time} s, interFoamAliasSafe;"
          f" addedMass: at most 10 outer correctors, tolerance"
          f" {args.tolerance}")
    print("| density (kg/m^3) | coupling | end reached | steps"
          " | outer correctors per step | CPU per simulated s |")
    print("|---|---|---|---|---|---|")
    comparisons = []
    for density in densities:
        runs = {}
        for name, kw in (
                ("stock", dict(coupling="stock")),
                ("hand", dict(coupling="stock",
                              relaxation=HAND_RELAXATION.get(density)))
                if density in HAND_RELAXATION else (None, None),
                ("addedMass3", dict(coupling="addedMass", tolerance=None)),
                ("addedMass", dict(coupling="addedMass",
                                   tolerance=args.tolerance))):
            if name is None:
                continue
            case = foc.make(base, os.path.join(work, f"{name}{density}"),
                            density, args.end_time, **kw)
            r = foc.solve(case)
            runs[name] = r
            label = {"stock": "rigidBodyMotion, relaxation 0.7",
                     "hand": f"rigidBodyMotion, relaxation "
                             f"{kw.get('relaxation')}",
                     "addedMass3": "addedMassRigidBodyMotion, 3 correctors",
                     "addedMass": "addedMassRigidBodyMotion, converged"}[name]
            print(row(label, density, r, args.end_time), flush=True)
        relaxed = runs.get("hand") if "hand" in runs else runs.get("stock")
        for name in ("addedMass3", "addedMass"):
            if relaxed and relaxed["ended"] and runs[name]["ended"]:
                comparisons.append((density, name) + foc.compare(runs[name],
                                                                 relaxed))
    print()
    print("| density (kg/m^3) | run against the relaxed one"
          " | max sway difference (m) | max pitch-sine difference"
          " | sway range of the run (m) |")
    print("|---|---|---|---|---|")
    for density, name, dy, dp, span in comparisons:
        print(f"| {density} | {name} | {dy:.2e} | {dp:.2e} | {span:.3f} |")
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()

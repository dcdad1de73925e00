#!/usr/bin/env python3
"""How many outer correctors a light body needs: the added-mass coupling at a
fixed number of outer correctors against a converged reference.

OpenFOAM's floatingObject tutorial (the box in sway and pitch,
interFoamAliasSafe, serial) at each density, to the same end time, with
addedMassRigidBodyMotion and no relaxation:

  N correctors  nOuterCorrectors N for every step (N from -correctors);
  reference     at most -reference-max correctors, a step ended when the
                coupling residual is below -reference-tolerance.

Prints, per density and N, the largest difference of sway and of the pitch
sine from the reference over the run, the sway difference as a share of the
reference's sway range, and the CPU per simulated second: the table of
docs/floating-stability.md ("How many outer correctors").

    tests/run-with-openfoam bench/lightBodies/correctors.py [-end-time 1.5]
        [-densities 100,30] [-correctors 1,2,3,5] [-keep DIR]
"""

import argparse
import os
import shutil
import tempfile

from foamfmi import floatingobject as foc


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-end-time", type=float, default=1.5)
    parser.add_argument("-densities", default="100,30")
    parser.add_argument("-correctors", default="1,2,3,5")
    parser.add_argument("-reference-tolerance", type=float, default=1e-3)
    parser.add_argument("-reference-max", type=int, default=30)
    parser.add_argument("-keep", help="keep the runs in this directory")
    args = parser.parse_args()

    work = args.keep or tempfile.mkdtemp(prefix="lightBodyCorrectors.")
    os.makedirs(work, exist_ok=True)
    base = foc.mesh(os.path.join(work, "mesh"))

    print(f"floatingObject tutorial to {args.end_time} s, interFoamAliasSafe,"
          f" addedMassRigidBodyMotion; reference: coupling residual below"
          f" {args.reference_tolerance}, at most {args.reference_max}"
          " outer correctors")
    print("| density (kg/m^3) | outer correctors | end reached"
          " | max sway difference (m) | share of the sway range"
          " | max pitch-sine difference | CPU per simulated s |")
    print("|---|---|---|---|---|---|---|")
    for density in (int(d) for d in args.densities.split(",")):
        case = foc.make(base, os.path.join(work, f"reference{density}"),
                        density, args.end_time, "addedMass",
                        tolerance=args.reference_tolerance,
                        max_outer=args.reference_max)
        reference = foc.solve(case)
        if not reference["ended"]:
            print(f"| {density} | reference | {reference['time']:.3g} s"
                  " | - | - | - | - |")
            continue
        sway_range = max(reference["y"]) - min(reference["y"])
        steps = max(reference["steps"], 1)
        print(f"| {density} | reference: {reference['correctors']/steps:.1f}"
              f" per step, {sum(reference['converged'])} of"
              f" {reference['steps']} steps converged"
              f" | {reference['time']:.3g} s (End) | 0 | 0 | 0"
              f" | {reference['cpu']/reference['time']:.1f} s |",
              flush=True)
        for n in (int(c) for c in args.correctors.split(",")):
            case = foc.make(base, os.path.join(work, f"outer{n}_{density}"),
                            density, args.end_time, "addedMass",
                            outer=n, tolerance=None)
            r = foc.solve(case)
            if not r["ended"]:
                print(f"| {density} | {n} | {r['time']:.3g} s"
                      " | - | - | - | - |", flush=True)
                continue
            dy, dp, _ = foc.compare(r, reference)
            print(f"| {density} | {n} | {r['time']:.3g} s (End)"
                  f" | {dy:.2e} | {100*dy/sway_range:.0f} %"
                  f" | {dp:.2e} | {r['cpu']/r['time']:.1f} s |", flush=True)
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A light floating body: OpenFOAM's coupling blows up, the added-mass
coupling converges in every time step.

OpenFOAM's floatingObject tutorial with the box at 30 kg/m^3 (0.9 kg; its
sway added mass is about 25 times that, docs/floating-stability.md), to
0.15 s with interFoamAliasSafe:

  - rigidBodyMotion with the tutorial's settings (Newmark,
    accelerationRelaxation 0.7, 3 outer correctors) must stop before the
    end: the relaxed fixed point amplifies the sway acceleration by
    0.7 (1 + m_a/m) - 1, about 17, per corrector;
  - addedMassRigidBodyMotion, no relaxation, at most 20 outer correctors,
    must reach the end with every time step ended by PIMPLE's
    residualControl on the coupling residual (below 1e-2: the bodies'
    accelerations changed by less than 1 % in the last corrector), the
    box within 0.1 m and 0.3 rad of its start (it floats, slightly
    disturbed: a blow-up goes far beyond);
  - bad coupling entries (maxIter 0, tolerance 2, addedMassInterval 0, an
    accelerationRelaxation with the added mass) stop the run at the start
    with a FatalIOError naming the entry.

Both runs carry a soft tether (OpenFOAM's linearSpring restraint): with a
linear restraint the rigid-body solve is affine in the load, so the
coupling's Newton iterations must end in at most two iterations (one
exact step, one to see it) at a residual below 1e-8 in every corrector; a
restraint evaluated at a stale state took 5 to 10 and diverged.
"""

import os
import sys

from foamfmi import cli, floatingobject as foc
from foamfmi.dictionary import substitute

DENSITY = 30
END_TIME = 0.15
TOLERANCE = 1e-2


def fail(message):
    print(f"FAIL [lightBody]: {message}")
    sys.exit(1)


def main(argv):
    p = cli.parser("lightBody.py", __doc__)
    cli.add_keep(p)
    with cli.scratch("lightBody.", p.parse_args(argv).keep) as work:
        base = foc.mesh(os.path.join(work, "mesh"))

        stock = foc.solve(foc.make(base, os.path.join(work, "stock"),
                                   DENSITY, END_TIME, "stock", tether=True))
        print(f"rigidBodyMotion, relaxation 0.7: t = {stock['time']} s of"
              f" {END_TIME} s, ended: {stock['ended']}")
        if stock["ended"]:
            fail("OpenFOAM's relaxed coupling reached the end with a"
                 f" {DENSITY} kg/m^3 body: the case no longer shows the"
                 " added-mass instability")

        coupled = foc.solve(foc.make(base, os.path.join(work, "addedMass"),
                                     DENSITY, END_TIME, "addedMass",
                                     tolerance=TOLERANCE, max_outer=20,
                                     tether=True))
        per_step = coupled["correctors"]/max(coupled["steps"], 1)
        print(f"addedMassRigidBodyMotion: t = {coupled['time']} s,"
              f" ended: {coupled['ended']}, {coupled['steps']} steps,"
              f" {per_step:.2f} outer correctors per step")
        if not coupled["ended"]:
            fail(f"the added-mass coupling stopped at t = {coupled['time']} s"
                 f" (log: {work}/addedMass/log.solver)")
        for i, (t, rs, ok) in enumerate(zip(coupled["times"],
                                            coupled["residuals"],
                                            coupled["converged"])):
            # the last corrector's residual is the one PIMPLE acted on:
            # the final corrector after the check is printed too
            if not ok or len(rs) < 2 or rs[-2] >= TOLERANCE:
                fail(f"time step {i + 1} (t = {t} s) did not converge:"
                     f" coupling residuals {rs}")
        worst = max(coupled["newton"], key=lambda n: (n[0], n[1]))
        print(f"Newton iterations per corrector at most {worst[0]}, final"
              f" residuals at most {max(n[1] for n in coupled['newton']):.2g}")
        for i, (iterations, residual) in enumerate(coupled["newton"]):
            if iterations > 2 or residual > 1e-8:
                fail(f"corrector {i + 1}: Newton took {iterations} iterations"
                     f" to a residual of {residual}: the trial solves are"
                     " not affine in the load")
        y0, p0 = coupled["y"][0], coupled["pitch"][0]
        dy = max(abs(y - y0) for y in coupled["y"])
        dp = max(abs(p - p0) for p in coupled["pitch"])
        print(f"largest sway change {dy:.3g} m, pitch-sine change {dp:.3g}")
        if dy > 0.1 or dp > 0.3:
            fail(f"the body moved {dy} m / {dp} from its start: not afloat")
        # Bad coupling entries stop the run when the motion solver is
        # built, naming the entry and what was expected
        for entry, value, expected in (
                ("maxIter", "0", "at least one Newton iteration"),
                ("tolerance", "2", "must be in (0, 1)"),
                ("addedMassInterval", "0", "must be at least 1")):
            case = foc.make(base, os.path.join(work, "bad" + entry), DENSITY,
                            END_TIME, "addedMass", tolerance=TOLERANCE)
            substitute(os.path.join(case, "constant", "dynamicMeshDict"),
                    r"^(\s*report\s+on;)",
                    rf"\1\n    coupling {{ {entry} {value}; }}")
            bad = foc.solve(case)
            log = open(os.path.join(case, "log.solver")).read()
            if bad["steps"] or "FOAM FATAL IO ERROR" not in log \
                    or f"{entry} = {value}" not in log or expected not in log:
                fail(f"coupling {{ {entry} {value}; }} did not stop the run"
                     f" with a FatalIOError naming it (log: {case})")
        relaxed = foc.make(base, os.path.join(work, "badRelaxation"), DENSITY,
                           END_TIME, "addedMass", tolerance=TOLERANCE)
        substitute(os.path.join(relaxed, "constant", "dynamicMeshDict"),
                r"^(\s*report\s+on;)", r"\1\n    accelerationRelaxation 0.5;")
        foc.solve(relaxed)
        log = open(os.path.join(relaxed, "log.solver")).read()
        if "FOAM FATAL IO ERROR" not in log \
                or "accelerationRelaxation 0.5" not in log:
            fail("accelerationRelaxation with the added-mass coupling did not"
                 f" stop the run naming it (log: {relaxed})")
        print("bad coupling entries stop the run, each named")
        print("PASS [lightBody]")


if __name__ == "__main__":
    main(sys.argv[1:])

"""Every connector FMU restarts exactly in rigidBodySim.

For each connector (linearSpring, linearDamper, hinge, catenary,
mooringLine and the third-party bungee of examples/customConnector) a
scene runs from 0 to T, writing at T/2, and a copy restarted from T/2 runs
to T. The restarted run must reproduce the uninterrupted one bit for bit:
the rigid-body state is written with 17 significant digits (writePrecision
17 reads back every double exactly) and the FMU state as the bytes of
fmi2SerializeFMUstate, so the restarted run repeats the same operations on
the same numbers. Every column of the bodies' motion and of the connector's
outputs is compared, with tolerance 0.

The mooringLine scene is the one that failed before the restore waited for
the inputs: its FMU computes the line's start shape from the fairlead
position when it leaves initialisation mode. The same scene with the
rigid-body solver implicitNewmark failed before the solver wrote its memory
(Newton matrix, algorithmic acceleration) with the time: the restarted run
rebuilt the matrix, and its Newton iterates differed within the tolerance
(mooringLine's dissipated power 1.3e-10 of its range, the catenary's shape
2.4e-4).
"""
import math
import os
import shutil
import sys

from foamfmi.bridgecase import Case, fmu_path, fmu_restraint, linear_spring, rigid_body, rigid_body_model
from foamfmi.implicitcase import ImplicitCase
import test_catenary_world as catenary
import test_hinge as hinge
import test_two_bodies as two_bodies

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "customConnector"))


def damper_model():
    """A body on a vertical slider, held by OpenFOAM's linearSpring and
    damped by the linearDamper FMU towards the fixed world."""
    return rigid_body_model(
        rigid_body("buoy", 2.0, 0.1, (0, 0, 0.3), "Pz"),
        linear_spring("spring", "buoy", (0, 0, 1), (0, 0, 0), 200, 0, 0.5)
        + fmu_restraint("damper", fmu_path("linearDamper"), "buoy",
                        {"damping": 3, "A.p": (0, 0, 0), "B.p": (0, 0, 1)}),
        "Newmark", g=(0, 0, -9.81))


# Folders made for a scene, removed at the end
SCRATCH = []


def bungee_model():
    import customfmu
    import test_bungee

    folder = customfmu.copy_example("restart")
    SCRATCH.append(folder)
    fmu, _ = customfmu.build(folder)
    return test_bungee.model(fmu, 40.0, 0.0, 1.0, -1.2, "symplectic")


def catenary_model():
    """The moored bodies of test_catenary_world, with their frame origins
    45 m above the fairleads: with the body at the origin, where an FMU that
    leaves initialisation before its inputs are set would put it, the
    fairlead lies below the seabed and mooringLine.fmu refuses to start."""
    force = 3e4
    x_eq, _ = catenary.span(force)
    text = catenary.model(force, x_eq - 2.0, 2e4)
    height = 45.0
    text = text.replace(f"({x_eq - 2.0} 0 0)", f"({x_eq - 2.0} 0 {height})")
    text = text.replace("A.p (0 0 0)", f"A.p (0 0 {-height})")
    assert text.count(f"0 {height})") == 2 and text.count(f"A.p (0 0 {-height})") == 2
    return text


def catenary_implicit_model():
    """The moored bodies, solved by implicitNewmark."""
    text = catenary_model()
    assert text.count("solver { type Newmark; }") == 1
    return text.replace("solver { type Newmark; }", "solver { type implicitNewmark; }")


# name: (model, connector outputs to compare, end time, time step, nIter,
# case class)
SCENES = {
    "linearSpring": (lambda: two_bodies.model("symplectic"), ["spring"], 1.0, 0.005, 2, Case),
    "linearDamper": (damper_model, ["damper"], 1.0, 0.002, 2, Case),
    "hinge": (lambda: hinge.model(1e4), ["pivot", "elbow"], 0.02, 1e-4, 1, Case),
    "catenary, mooringLine": (catenary_model, ["mooring", "line"], 4.0, 0.02, 2, Case),
    "catenary, mooringLine, implicitNewmark": (catenary_implicit_model, ["mooring", "line"], 4.0,
                                               0.02, 2, ImplicitCase),
    "bungee (customConnector)": (bungee_model, ["bungee"], 2.0, 0.001, 1, Case),
}


def largest_difference(full, part):
    """(largest difference, its column) over every column but Time for the
    rows of part, matched to the rows of full at the same times; inf when
    rows are missing or the times do not match. Times may differ in the
    last bits: the uninterrupted run's time is a sum of steps
    (0.50000000000000033), the restarted one starts from the directory name
    (0.5)."""
    offset = len(full["Time"]) - len(part["Time"])
    if offset < 0 or not part["Time"]:
        return math.inf, "rows"
    if any(abs(a - b) > 1e-12 for a, b in zip(full["Time"][offset:], part["Time"])):
        return math.inf, "Time"
    return max(
        (abs(a - b), name)
        for name in full if name != "Time"
        for a, b in zip(full[name][offset:], part[name])
    )


def check_scene(name, make_model, connectors, end_time, delta_t, n_iter, case_class):
    text = make_model()
    half = end_time / 2
    full = case_class("restartAll", text, end_time, delta_t, write_interval=half)
    full.run(n_iter=n_iter)

    restarted = case_class("restartAll.half", text, end_time, delta_t, write_interval=half)
    written = sorted(
        (d for d in os.listdir(full.dir) if d.replace(".", "").isdigit() and float(d) > 0),
        key=float,
    )
    start = written[0]
    shutil.copytree(os.path.join(full.dir, start), os.path.join(restarted.dir, start))
    restarted.set_time(start, end_time, delta_t, half)
    log = restarted.run(n_iter=n_iter)

    worst = largest_difference(full.bodies(), restarted.bodies(start=start))
    for connector in connectors:
        difference, column = largest_difference(
            full.connector(connector), restarted.connector(connector, start=start)
        )
        worst = max(worst, (difference, f"{connector}.{column}"))
    restored = all(f"Connector {c}: FMU state restored at t = " in log for c in connectors)

    full.cleanup()
    restarted.cleanup()
    # Tolerance 0: the same operations on the same (exactly restored)
    # numbers give the same bits.
    ok = restored and worst[0] == 0.0
    print(f"{'PASS' if ok else 'FAIL'} {name}: restart from t = {start}, "
          f"FMU state restored {restored}, largest difference {worst[0]:.3g} ({worst[1]})",
          flush=True)
    return ok


def main():
    failures = 0
    for name, scene in SCENES.items():
        try:
            ok = check_scene(name, *scene)
        except AssertionError as error:
            print(f"FAIL {name}: {str(error)[-1500:]}", flush=True)
            ok = False
        failures += 0 if ok else 1
    for folder in SCRATCH:
        shutil.rmtree(folder, ignore_errors=True)
    print(f"{len(SCENES) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

"""Restarts of the sixDoF connector tutorial in interFoam, serial and
parallel, as tests/tutorials/restart.py does for the rigidBodyMotion ones.

coupledFloatingObjectsSixDoF (the spring between two
sixDoFRigidBodyDisplacement patches, one FMU shared by their restraints)
runs on the coarse mesh to T = 0.2 s, writing at 0.1 s in binary with 17
digits; a copy restarted from 0.1 s (startFrom latestTime) runs to T. The
point-patch condition writes each body's motion, with its restraints, into
pointDisplacement; the connector's state goes to uniform/fmuConnectors.
Checked for every run:

- the restart runs to T and restores the connector's FMU state, once;
- the connector writes one row per time step after the restart, at the
  uninterrupted run's times;
- the bodies' state at T (orientation and angular velocity of the last
  report of each body in the solver log) stays within OpenFOAM's own
  restart floor, measured on uncoupledFloatingObjectsSixDoF (no connector),
  times 10 for the coupled dynamics, and at most 2 %: v1912's interFoam does
  not restart exactly (docs/restarts.md), the connector does
  (tests/bridge/test_sixdof_spring_world.py, bit for bit).
"""
import os
import re
import shutil
import sys
import tempfile

from restart import END, HALF, rows, run, set_entry, TOP

SCENES = {
    "uncoupledFloatingObjectsSixDoF": ([], []),
    "coupledFloatingObjectsSixDoF": (["spring"], []),
    "coupledFloatingObjectsSixDoF -parallel": (["spring"], ["-parallel"]),
}


def body_state(log):
    """Orientation and angular velocity of the last report of each of the
    two bodies (the motions report in patch order every solve)."""
    with open(log) as f:
        text = f.read()
    orientations = re.findall(r"Orientation: \(([^)]*)\)", text)[-2:]
    omegas = re.findall(r"Angular velocity: \(([^)]*)\)", text)[-2:]
    return [float(x) for block in orientations + omegas for x in block.split()]


def relative_difference(a, b):
    scale = max(abs(x) for x in a) or 1.0
    return max(abs(x - y) for x, y in zip(a, b)) / scale


def run_scene(work, name, connectors, options):
    tutorial = name.split()[0]
    parallel = "-parallel" in options
    full = os.path.join(work, name.replace(" ", ""), "full")
    shutil.copytree(os.path.join(TOP, "tutorials", tutorial), full)
    control = os.path.join(full, "system", "controlDict")
    set_entry(control, "writeFormat", "binary")
    set_entry(control, "writePrecision", "17")
    set_entry(control, "writeInterval", HALF)
    run(["./Allrun", "-mesh-factor", "0.5", "-end-time", END, "-no-plot"] + options, full, "log.Allrun")

    restarted = os.path.join(os.path.dirname(full), "restarted")
    shutil.copytree(full, restarted, ignore=shutil.ignore_patterns("postProcessing", "log.*"))
    for base in [restarted] + [os.path.join(restarted, p) for p in ("processor0", "processor1") if parallel]:
        shutil.rmtree(os.path.join(base, END), ignore_errors=True)
    set_entry(os.path.join(restarted, "system", "controlDict"), "startFrom", "latestTime")
    solver = "interFoamAliasSafe"
    if parallel:
        run(["mpirun", "-np", "2", solver, "-parallel"], restarted, "log.restart")
    else:
        run([solver], restarted, "log.restart")
    with open(os.path.join(restarted, "log.restart")) as f:
        log = f.read()

    problems = []
    for c in connectors:
        restored = log.count(f"Connector {c}: FMU state restored at t = 0.1")
        if restored != 1:
            problems.append(f"{c}: state restored {restored} times")
        a = rows(os.path.join(full, "postProcessing", "fmuConnectors", "0", c + ".dat"))
        b = rows(os.path.join(restarted, "postProcessing", "fmuConnectors", HALF, c + ".dat"))
        tail = [r for r in a if r[0] > float(HALF) + 1e-9]
        if len(b) != len(tail) or any(abs(x[0] - y[0]) > 1e-9 for x, y in zip(tail, b)):
            problems.append(f"{c}: {len(b)} rows after the restart for {len(tail)}")
    difference = relative_difference(
        body_state(os.path.join(full, "log.interFoamAliasSafe")),
        body_state(os.path.join(restarted, "log.restart")))
    return problems, difference


def main():
    for var in ("FOAMFMI_DIR", "FOAM_USER_APPBIN"):
        if var not in os.environ:
            raise SystemExit(f"{var} is not set: run through tests/run-with-openfoam")
    if os.getuid() == 0:  # mpirun refuses root without these
        os.environ["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
        os.environ["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"

    work = tempfile.mkdtemp(prefix="tutorialRestartSixDoF.")
    failures = 0
    floor = None
    for name, (connectors, options) in SCENES.items():
        try:
            problems, difference = run_scene(work, name, connectors, options)
        except AssertionError as error:
            problems, difference = [str(error)], float("inf")
        if floor is None:
            floor = difference
            print(f"{'PASS' if not problems else 'FAIL'} {name}: OpenFOAM's restart floor, "
                  f"body state at t = {END} differs by {difference:.2e} relative {problems}", flush=True)
            failures += 1 if problems else 0
            continue
        bound = min(max(10 * floor, 1e-12), 0.02)
        ok = not problems and difference <= bound
        failures += 0 if ok else 1
        print(f"{'PASS' if ok else 'FAIL'} {name}: restored {connectors}, body state at t = {END} "
              f"differs by {difference:.2e} relative (bound {bound:.2e}) {problems}", flush=True)

    if failures == 0:
        shutil.rmtree(work, ignore_errors=True)
    else:
        print(f"the runs are kept in {work}")
    print(f"{len(SCENES) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

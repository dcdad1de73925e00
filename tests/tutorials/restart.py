"""Restarts of the connector tutorials in interFoam, serial and parallel.

Each connector's tutorial (spring, damper, hinge, quasi-static and dynamic
mooring lines) runs on the coarse mesh (mesh factor 0.5) to T = 0.2 s,
writing at 0.1 s in binary with 17 digits; a copy restarted from 0.1 s
(startFrom latestTime) runs to T. The spring scene is also run on 2
processors. Checked for every run:

- the restart runs to T and restores every connector's FMU state, once;
- every connector writes one row per time step after the restart, at the
  uninterrupted run's times;
- a case with lines in the flow (fmuConnectorFlow) restores the water
  velocities written at the restart time, once;
- a line's VTK series lists each write time once: the restart replaces the
  entry of the time it writes again (T) and keeps the earlier one;
- the restarted run stays within OpenFOAM's own restart floor: v1912's
  interFoam does not restart exactly (docs/restarts.md: MULES keeps its
  previous correction in memory only, Crank-Nicolson restarts its old-time
  derivative); measured here on the uncoupled cubes, which have no
  connector, their body state at T differs by about 7e-3 relative
  (v2312's interFoam: 5.4e-2). The connectors restore exactly
  (tests/bridge/test_restart_connectors.py, bit for bit), so a coupled
  scene may differ by no more than that floor times a margin for its
  different dynamics (10), and by at most 2 %, or twice the floor where
  OpenFOAM's own floor is above 1 % (v2312: the coupled cubes 5.0e-2, the
  damped ones 5.5e-2, against the uncoupled cubes' 5.4e-2).

The dynamic-line scene is the one that could not restart before: its FMU
computed the line's start shape from an unset fairlead position.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from foamfmi import postprocessing
from foamfmi.dictionary import set_entry

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
END, HALF = "0.2", "0.1"

# tutorial: (connectors, extra Allrun arguments)
SCENES = {
    "uncoupledFloatingObjects": ([], []),
    "coupledFloatingObjects": (["spring"], []),
    "coupledFloatingObjects -parallel": (["spring"], ["-parallel"]),
    "damperFloatingObjects": (["damper"], []),
    "hingedFloatingObjects": (["hinge"], []),
    "mooredFloatingObject": (["line1", "line2", "line3", "line4"], []),
    "mooredFloatingObjectDynamic": (["line1", "line2", "line3", "line4"], []),
}


def run(command, cwd, log):
    with open(os.path.join(cwd, log), "w") as out:
        code = subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT).returncode
    if code:
        with open(os.path.join(cwd, log)) as f:
            tail = f.read()[-2000:]
        raise AssertionError(f"{' '.join(command)} failed in {cwd}:\n{tail}")


def rows(path):
    with open(path) as f:
        return [[float(x) for x in line.split()] for line in f if line.strip() and not line.startswith("#")]


def body_state(full, restarted, parallel):
    """q and qDot of the rigid-body model at END, in the uninterrupted and
    the restarted run."""
    def state(case):
        base = os.path.join(case, "processor0") if parallel else case
        with open(os.path.join(base, END, "uniform", "rigidBodyMotionState")) as f:
            text = f.read()
        values = []
        for key in ("q", "qDot"):
            m = re.search(rf"\n{key}\s+\d+\s*\(([^)]*)\)", text)
            values += [float(x) for x in m.group(1).split()]
        return values

    return state(full), state(restarted)


def relative_difference(a, b):
    scale = max(abs(x) for x in a) or 1.0
    return max(abs(x - y) for x, y in zip(a, b)) / scale


def run_scene(work, name, connectors, options, states):
    """Runs a tutorial to END writing at HALF and a copy restarted from
    HALF; returns (problems, relative difference of the bodies' states at
    END), states(full, restarted, parallel) giving those states."""
    tutorial = name.split()[0]
    parallel = "-parallel" in options
    full = os.path.join(work, name.replace(" ", ""), "full")
    shutil.copytree(os.path.join(TOP, "tutorials", tutorial), full)
    # Whatever a user has run in the tutorial (./Allrun, the main job) is
    # not part of the copy
    run(["./Allclean"], full, "log.Allclean")
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
    solver = postprocessing.case_solver(full)
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
        series = os.path.join(restarted, "VTK", "fmuConnectors", c + ".vtk.series")
        if os.path.exists(series):
            with open(series) as f:
                times = [e["time"] for e in json.load(f)["files"]]
            expected = [float(HALF), float(END)]
            if len(times) != 2 or any(abs(x - y) > 1e-9 for x, y in zip(times, expected)):
                problems.append(f"{c}: VTK series times {times} after the restart, expected {expected}")
    flow_states = os.path.join(full, "processor0" if parallel else "", HALF, "uniform", "fmuConnectorFlow")
    if os.path.isdir(flow_states):
        restored = log.count("water velocity at the lines restored from")
        if restored != 1:
            problems.append(f"water velocity at the lines restored {restored} times")
    difference = relative_difference(*states(full, restarted, parallel))
    return problems, difference


def check_scenes(scenes, states, prefix):
    """Runs every scene (the first without connectors: OpenFOAM's floor);
    prints a line per scene and the count; returns the exit code."""
    for var in ("FOAMFMI_DIR", "FOAM_USER_APPBIN"):
        if var not in os.environ:
            raise SystemExit(f"{var} is not set: run through tests/run-with-openfoam")
    if os.getuid() == 0:  # mpirun refuses root without these
        os.environ["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
        os.environ["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"

    work = tempfile.mkdtemp(prefix=prefix)
    failures = 0
    floor = None
    for name, (connectors, options) in scenes.items():
        try:
            problems, difference = run_scene(work, name, connectors, options, states)
        except AssertionError as error:
            problems, difference = [str(error)], float("inf")
        if floor is None:
            # The uncoupled cubes: OpenFOAM's own restart floor
            floor = difference
            print(f"{'PASS' if not problems else 'FAIL'} {name}: OpenFOAM's restart floor, "
                  f"body state at t = {END} differs by {difference:.2e} relative {problems}", flush=True)
            failures += 1 if problems else 0
            continue
        bound = min(max(10 * floor, 1e-12), max(0.02, 2 * floor))
        ok = not problems and difference <= bound
        failures += 0 if ok else 1
        print(f"{'PASS' if ok else 'FAIL'} {name}: restored {connectors}, body state at t = {END} "
              f"differs by {difference:.2e} relative (bound {bound:.2e}) {problems}", flush=True)

    if failures == 0:
        shutil.rmtree(work, ignore_errors=True)
    else:
        print(f"the runs are kept in {work}")
    print(f"{len(scenes) - failures} passed, {failures} failed")
    return 1 if failures else 0


def main():
    return check_scenes(SCENES, body_state, "tutorialRestart.")


if __name__ == "__main__":
    sys.exit(main())

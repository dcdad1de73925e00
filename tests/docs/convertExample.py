"""docs/convert.md's example as written: OpenFOAM's floatingObject tutorial
with the page's built-in restraints (a spring to the tank wall, stretched at
the start, and a linearDamper), in rigidBodyMotion (the tutorial's
dynamicMeshDict) and in sixDoFRigidBodyMotion (its dynamicMeshDict.sixDoF),
each run as it is and after foamFmiConvert, with the same controls, to
END_TIME. Checks, per framework:
  - the converter replaces both restraints, copies both FMUs and loads the
    library (the built-in case has no libs entry);
  - both runs reach END_TIME;
  - the mesh points (the body's patch and the mesh moving with it), written
    at every WRITE_INTERVAL with 12 digits, agree to 1e-5 of the largest
    displacement of a point over the run (tolerance below);
  - the body moves and the converted spring pulls (so that the comparison
    is not made on a body at rest or a slack spring).
The mesh tools and the solver take the CFD lock (/tmp/foamfmi-cfd.lock)
for each run (foamfmi.floatingobject).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import textwrap

from foamfmi import floatingobject
from foamfmi.dictionary import read_points, set_entry

END_TIME = 0.5
WRITE_INTERVAL = 0.05
TOP = os.environ["FOAMFMI_DIR"]
failures = 0


def check(ok, message):
    global failures
    failures += not ok
    print(("PASS " if ok else "FAIL ") + message, flush=True)
    return ok


def blocks():
    """The page's example blocks: {name: text}."""
    with open(os.path.join(TOP, "docs", "convert.md")) as f:
        text = f.read()
    found = dict(re.findall(r"<!-- convert example: (\S+) -->\n(.*?)<!-- convert example: end -->",
                            text, re.S))
    for name in ("rigidBodyMotion", "sixDoFRigidBodyMotion"):
        if name not in found:
            sys.exit(f"docs/convert.md: no example block {name}")
    return {name: textwrap.dedent(block) for name, block in found.items()}


def make_case(base, path, sixdof, restraints):
    """A copy of the meshed tutorial with the restraints, the solver, the
    end time and the write interval set; no libs entry."""
    shutil.copytree(base, path, ignore=shutil.ignore_patterns("log.*"))
    if sixdof:
        with open(os.path.join(path, "constant", "dynamicMeshDict"), "w") as f:
            f.write(floatingobject.sixdof_dictionary())
    floatingobject.add_restraints(path, restraints)
    control = os.path.join(path, "system", "controlDict")
    solver = "interFoamAliasSafe" if shutil.which("interFoamAliasSafe") else "interFoam"
    set_entry(control, "application", solver, 16)
    set_entry(control, "endTime", END_TIME, 16)
    set_entry(control, "writeInterval", WRITE_INTERVAL, 16)
    return solver


def write_times(case):
    return sorted((d for d in os.listdir(case)
                   if re.fullmatch(r"[0-9.e-]+", d) and float(d) > 0), key=float)


def compare_points(builtin, converted, framework):
    times = write_times(builtin)
    if not check(times == write_times(converted) and len(times) >= 5,
                 f"{framework}: the same write times, {len(times)} of them"):
        return
    start = read_points(os.path.join(builtin, "constant", "polyMesh", "points"))
    worst = largest = 0.0
    for t in times:
        a = read_points(os.path.join(builtin, t, "polyMesh", "points"))
        b = read_points(os.path.join(converted, t, "polyMesh", "points"))
        worst = max(worst, max(abs(u - v) for p, q in zip(a, b) for u, v in zip(p, q)))
        largest = max(largest, max(abs(u - v) for p, q in zip(a, start) for u, v in zip(p, q)))
    # The built-in restraint and the FMU compute the same loads from the
    # same state in another order of operations (round-off, 1e-16
    # relative); the flow solution, iterated to its solvers' tolerances,
    # carries such differences on without growing them much over 0.5 s. The
    # points are written with 12 digits. 1e-5 of the largest displacement
    # leaves room for that and is far below what a wrong attachment point
    # (0.25 m off), anchor, stiffness or damping changes: percents of it.
    check(worst <= 1e-5 * largest and largest > 1e-3,
          f"{framework}: the converted case moves the mesh as the built-in one: largest "
          f"difference {worst:.3g} m, {worst / largest if largest else 0:.3g} of the largest "
          f"displacement {largest:.4g} m (tolerance 1e-5)")


def largest_tension(case):
    path = os.path.join(case, "postProcessing", "fmuConnectors", "0", "spring.dat")
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                names = line[1:].split()
            elif line.strip():
                rows.append(line.split())
    column = names.index("tension")
    return max(abs(float(row[column])) for row in rows)


def main():
    example = blocks()
    work = tempfile.mkdtemp(prefix="convertExample.")
    base = floatingobject.mesh(os.path.join(work, "base"))
    for framework, sixdof in (("rigidBodyMotion", False), ("sixDoFRigidBodyMotion", True)):
        builtin = os.path.join(work, framework + "Builtin")
        converted = os.path.join(work, framework + "Converted")
        solver = make_case(base, builtin, sixdof, example[framework])
        shutil.copytree(builtin, converted)
        done = subprocess.run([os.path.join(TOP, "bin", "foamFmiConvert"), converted],
                              capture_output=True, text=True)
        print(done.stdout + done.stderr, end="")
        fmus = sorted(os.listdir(os.path.join(converted, "constant", "fmu"))) \
            if os.path.isdir(os.path.join(converted, "constant", "fmu")) else []
        with open(os.path.join(converted, "system", "controlDict")) as f:
            libs = '"libfoamFmiBridge.so"' in f.read()
        check(done.returncode == 0 and done.stdout.count(": fmuConnector ") == 2 and libs
              and fmus == ["linearSpring.fmu", "translationalDamper.fmu"],
              f"{framework}: foamFmiConvert replaced 2 restraints, copied {' '.join(fmus)}, "
              f"libs {'added' if libs else 'missing'}")
        for case in (builtin, converted):
            run = floatingobject.solve(case, solver)
            check(run["ended"] and abs(run["time"] - END_TIME) < 1e-9,
                  f"{os.path.basename(case)}: {solver} ran to t = {run['time']} s "
                  f"({run['steps']} steps, {run['cpu']} s CPU)")
        compare_points(builtin, converted, framework)
        tension = largest_tension(converted)
        # the spring starts 0.05 m over its rest length: 5 N
        check(tension > 1.0, f"{framework}: the converted spring pulls, largest tension "
              f"{tension:.3g} N")
    print(f"{'FAIL' if failures else 'PASS'}: {failures} failed; runs in {work}")
    if not failures and os.environ.get("KEEP_CASES") != "1":
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

"""foamFmiConvert on OpenFOAM's own tutorials: built-in restraints against
the converted case, run as they are and after the conversion with the same
controls.

    convertExample.py floatingObject   (test docs.convertExample)
    convertExample.py floatingBody     (test docs.convertOverset)

floatingObject: docs/convert.md's example as written, OpenFOAM's
floatingObject with the page's built-in restraints (a spring to the tank
wall, stretched at the start, and a linearDamper), in rigidBodyMotion (the
tutorial's dynamicMeshDict) and in sixDoFRigidBodyMotion (its
dynamicMeshDict.sixDoF), to END_TIME.

floatingBody: OpenFOAM's overset floatingBody (overInterDyMFoam, sixDoF,
a line constraint along z, rotations free) on meshes 4 times coarser in
each direction (its cube then 4 cells wide), with a spring to the world
(attached off the top's centre, so that it turns the body), a
sphericalAngularDamper and a linearAxialAngularSpring about y (the axis the
spring turns the body about), to OVERSET_END_TIME. OpenFOAM's sixDoF linearDamper
is left out here: it applies its force at the global origin, a moment that
this body, free to turn, would feel and its twin does not
(docs/convert.md).

Checks, per case:
  - the converter replaces the restraints, copies their FMUs and loads the
    library (the built-in case has no libs entry);
  - both runs reach the end time;
  - the mesh points (the body's patch and the mesh moving with it), written
    at every write interval with 12 digits, agree to 1e-5 of the largest
    displacement of a point over the run (tolerance below);
  - the body moves and the converted spring pulls (so that the comparison
    is not made on a body at rest or a slack spring);
  - tutorials/bin/renderScene draws every connector of the converted case
    at its last time with no step before it (the bodies placed by the
    state OpenFOAM wrote: no table of their motion exists), where ParaView
    is installed.
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
from foamfmi.dictspan import dictionary_spans

END_TIME = 0.5
OVERSET_END_TIME = 0.3
WRITE_INTERVAL = 0.05
OVERSET = os.path.join(os.path.dirname(floatingobject.TUTORIAL), "..", "..",
                       "overInterDyMFoam", "floatingBody")
# Anchor above the cube, attachment 0.06 m off the centre of its top face
# (0.5 0.5 0.6): 0.1 m over the rest length at the start, about 20 N
OVERSET_RESTRAINTS = """restraints
{
    spring
    {
        sixDoFRigidBodyMotionRestraint linearSpring;
        anchor          (0.6 0.5 1.0);
        refAttachmentPt (0.56 0.5 0.6);
        stiffness       200;
        damping         2;
        restLength      0.3;
    }
    turning
    {
        sixDoFRigidBodyMotionRestraint sphericalAngularDamper;
        coeff           0.5;
    }
    twist
    {
        sixDoFRigidBodyMotionRestraint linearAxialAngularSpring;
        axis            (0 1 0);
        referenceOrientation (1 0 0 0 1 0 0 0 1);
        stiffness       20;
        damping         0.5;
    }
}
"""
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


def make_case(base, path, sixdof, restraints, solver="interFoam", end_time=END_TIME):
    """A copy of the meshed tutorial with the restraints, the solver (the
    project's rebuilt one where there is one), the end time and the write
    interval set; no libs entry. The case's folder and its solver."""
    shutil.copytree(base, path, ignore=shutil.ignore_patterns("log.*"))
    if os.path.isdir(os.path.join(path, "background")):
        path = os.path.join(path, "background")
    mesh_dict = os.path.join(path, "constant", "dynamicMeshDict")
    if sixdof is True:
        text = floatingobject.sixdof_dictionary()
    elif sixdof:
        text = floatingobject.sixdof_dictionary(path=sixdof)
    if sixdof:
        with open(mesh_dict, "w") as f:
            f.write(text)
    floatingobject.add_restraints(path, restraints)
    control = os.path.join(path, "system", "controlDict")
    if shutil.which(solver + "AliasSafe"):
        solver += "AliasSafe"
    # floatingBody's function objects out: its coded alphaVol is dynamic
    # code, which OpenFOAM compiles for no root
    with open(control) as f:
        text = f.read()
    span = dictionary_spans(text, control).get(("functions",))
    if span:
        with open(control, "w") as f:
            f.write(text[:span[0]] + text[span[1]:])
    set_entry(control, "application", solver, 16)
    set_entry(control, "endTime", end_time, 16)
    set_entry(control, "writeInterval", WRITE_INTERVAL, 16)
    return path, solver


def overset_mesh(base):
    """OpenFOAM's floatingBody meshed as its Allrun.pre does, each block
    with 4 times fewer cells in each direction (the cube's faces stay on
    cell faces)."""
    shutil.copytree(OVERSET, base)
    for part, old, new in (("floatingBody", "(40 40 45)", "(10 10 14)"),
                           ("background", "(80 80 70)", "(24 24 20)")):
        path = os.path.join(base, part, "system", "blockMeshDict")
        with open(path) as f:
            text = f.read()
        if old not in text:
            sys.exit(f"{path}: no block of {old} cells")
        with open(path, "w") as f:
            f.write(text.replace(old, new))
    for part, command in (("floatingBody", ["blockMesh"]), ("floatingBody", ["topoSet"]),
                          ("floatingBody", ["subsetMesh", "-overwrite", "c0", "-patch",
                                            "floatingObject"]),
                          ("background", ["blockMesh"]),
                          ("background", ["mergeMeshes", ".", "../floatingBody", "-overwrite"]),
                          ("background", ["topoSet"])):
        if floatingobject.run(os.path.join(base, part), *command) != 0:
            sys.exit(f"{command[0]} failed in {os.path.join(base, part)}")
    shutil.copytree(os.path.join(base, "background", "0.orig"),
                    os.path.join(base, "background", "0"))
    if floatingobject.run(os.path.join(base, "background"), "setFields") != 0:
        sys.exit(f"setFields failed in {os.path.join(base, 'background')}")
    return base


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


def convert_and_run(base, work, name, sixdof, restraints, fmus, solver, end_time):
    """Both cases of one scene: made, converted, run and compared."""
    top = os.path.join(work, name + "Builtin")
    builtin, solver = make_case(base, top, sixdof, restraints, solver, end_time)
    shutil.copytree(top, os.path.join(work, name + "Converted"))
    converted = builtin.replace(top, os.path.join(work, name + "Converted"))
    done = subprocess.run([os.path.join(TOP, "bin", "foamFmiConvert"), converted],
                          capture_output=True, text=True)
    print(done.stdout + done.stderr, end="")
    copied = sorted(os.listdir(os.path.join(converted, "constant", "fmu"))) \
        if os.path.isdir(os.path.join(converted, "constant", "fmu")) else []
    with open(os.path.join(converted, "system", "controlDict")) as f:
        libs = '"libfoamFmiBridge.so"' in f.read()
    check(done.returncode == 0 and done.stdout.count(": fmuConnector ") == len(fmus) and libs
          and copied == sorted(fmus),
          f"{name}: foamFmiConvert replaced {len(fmus)} restraints, copied {' '.join(copied)}, "
          f"libs {'added' if libs else 'missing'}")
    for case in (builtin, converted):
        run = floatingobject.solve(case, solver)
        check(run["ended"] and abs(run["time"] - end_time) < 1e-9,
              f"{os.path.relpath(case, work)}: {solver} ran to t = {run['time']} s "
              f"({run['steps']} steps, {run['cpu']} s CPU)")
    compare_points(builtin, converted, name)
    tension = largest_tension(converted)
    # both springs start 0.05-0.1 m over their rest length: 5-20 N
    check(tension > 1.0, f"{name}: the converted spring pulls, largest tension {tension:.3g} N")
    render(converted, work, name, len(fmus))


def render(case, work, name, n_connectors):
    """renderScene on the converted case as it is after its run: every
    connector drawn, no body without its motion."""
    if shutil.which("pvbatch") is None:
        print(f"SKIP {name}: renderScene (no pvbatch: Debian packages paraview, "
              "python3-paraview)")
        return
    png = os.path.join(work, name + ".png")
    done = subprocess.run([os.path.join(TOP, "tutorials", "bin", "renderScene"), "-output", png,
                           case], capture_output=True, text=True)
    text = done.stdout + done.stderr
    drawn = [line for line in text.splitlines() if line.startswith("renderScene: wrote")]
    counts = [(int(a), int(b)) for a, b in re.findall(r"\b(\d+) of (\d+)", "".join(drawn[:1]))]
    check(done.returncode == 0 and drawn and all(a == b for a, b in counts)
          and sum(b for a, b in counts) == n_connectors and "no motion of" not in text
          and not os.path.isdir(os.path.join(case, "postProcessing", "rigidBodyMotion")),
          f"{name}: renderScene drew every connector from the written state: "
          f"{drawn[0] if drawn else text[-800:]}")


def main(scene):
    work = tempfile.mkdtemp(prefix="convertExample.")
    if scene == "floatingObject":
        example = blocks()
        base = floatingobject.mesh(os.path.join(work, "base"))
        for framework, sixdof in (("rigidBodyMotion", False), ("sixDoFRigidBodyMotion", True)):
            convert_and_run(base, work, framework, sixdof, example[framework],
                            ["linearSpring.fmu", "translationalDamper.fmu"], "interFoam",
                            END_TIME)
    elif scene == "floatingBody":
        base = overset_mesh(os.path.join(work, "base"))
        convert_and_run(base, work, "oversetSixDoF",
                        os.path.join(OVERSET, "background", "constant", "dynamicMeshDict"),
                        OVERSET_RESTRAINTS, ["axialAngularSpring.fmu", "linearSpring.fmu",
                                             "rotationalDamper.fmu"],
                        "overInterDyMFoam", OVERSET_END_TIME)
    else:
        sys.exit(f"convertExample.py: no scene {scene} (floatingObject, floatingBody)")
    print(f"{'FAIL' if failures else 'PASS'}: {failures} failed; runs in {work}")
    if not failures and os.environ.get("KEEP_CASES") != "1":
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "floatingObject"))

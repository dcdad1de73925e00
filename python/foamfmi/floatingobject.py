"""OpenFOAM's floatingObject tutorial (interFoam/RAS) as a light-body case.

The tutorial's box (0.3 x 0.2 x 0.5 m, sway Py and pitch Ry) with a chosen
density, coupled to the fluid either by OpenFOAM's own rigidBodyMotion
(Newmark, a constant accelerationRelaxation, a fixed number of outer
correctors) or by the project's addedMassRigidBodyMotion (no relaxation,
the outer correctors ended by the coupling residual). Used by
tests/floatingStability/lightBody.py and bench/lightBodies/run.py.
"""

import os
import re
import shutil
import subprocess

from foamfmi.dictionary import substitute

TUTORIAL = os.path.join(
    os.environ.get("FOAM_TUTORIALS", "/usr/share/doc/openfoam-examples/examples"),
    "multiphase/interFoam/RAS/floatingObject")

LOCK = "/tmp/foamfmi-cfd.lock"


def run(case, *command):
    """Run command in case under the CFD lock (one mesh job at a time on
    this machine), its output to log.<command>; its exit code."""
    log = os.path.join(case, "log." + os.path.basename(command[0]))
    with open(log, "w") as out:
        return subprocess.run(["flock", LOCK, *command], cwd=case, stdout=out,
                              stderr=subprocess.STDOUT).returncode


def mesh(base):
    """The tutorial's mesh and initial fields in base (made once)."""
    if os.path.isdir(os.path.join(base, "constant", "polyMesh")):
        return base
    shutil.rmtree(base, ignore_errors=True)
    os.makedirs(base)
    for d in ("system", "constant"):
        shutil.copytree(os.path.join(TUTORIAL, d), os.path.join(base, d))
    shutil.copytree(os.path.join(TUTORIAL, "0.orig"), os.path.join(base, "0"))
    for command in (["blockMesh"], ["topoSet"],
                    ["subsetMesh", "-overwrite", "c0", "-patch",
                     "floatingObject"], ["setFields"]):
        if run(base, *command) != 0:
            raise RuntimeError(f"{command[0]} failed in {base}")
    return base


def sixdof_dictionary(tutorial=TUTORIAL, path=None):
    """The text of the tutorial's constant/dynamicMeshDict.sixDoF (or of
    the file path, a sixDoF dictionary written alike: OpenFOAM's overset
    floatingBody) with its #codeStream moment of inertia replaced by the
    value it computes from the same entries: OpenFOAM refuses to compile
    dynamic code for root (dynamicCode's security check), and tests run as
    root in containers."""
    path = path or os.path.join(tutorial, "constant", "dynamicMeshDict.sixDoF")
    with open(path) as f:
        text = f.read()
    size = []
    for key in ("Lx", "Ly", "Lz", "rhoSolid"):
        m = re.search(rf"\n\s*{key}\s+([^;]+);", text)
        if not m:
            raise RuntimeError(f"{path}: no entry {key}")
        size.append(float(m.group(1)))
    mass = size[0] * size[1] * size[2] * size[3]
    x2, y2, z2 = (v * v for v in size[:3])
    inertia = (mass * (y2 + z2) / 12, mass * (x2 + z2) / 12, mass * (x2 + y2) / 12)
    text, n = re.subn(r"momentOfInertia\s+#codeStream\s*\{.*?\n    \};",
                      "momentOfInertia (%.17g %.17g %.17g);" % inertia, text, flags=re.S)
    if n != 1:
        raise RuntimeError(f"{path}: no #codeStream momentOfInertia")
    return text


def add_restraints(case, block):
    """Put the restraints' text block (a 'restraints { ... }' entry) first
    in the motion's coefficients of case's constant/dynamicMeshDict."""
    path = os.path.join(case, "constant", "dynamicMeshDict")
    with open(path) as f:
        text = f.read()
    head = re.search(r"\n(rigidBodyMotionCoeffs|sixDoFRigidBodyMotionCoeffs)\s*\n\{\n", text)
    if not head:
        raise RuntimeError(f"{path}: no rigidBodyMotionCoeffs or sixDoFRigidBodyMotionCoeffs")
    block = "".join("    " + line if line.strip() else line
                    for line in block.splitlines(True))
    with open(path, "w") as f:
        f.write(text[:head.end()] + block + text[head.end():])


TETHER = """
    // A soft horizontal tether from the body's centre of mass to a fixed
    // anchor 0.15 m away in y: OpenFOAM's linearSpring restraint, unloaded
    // at the start
    restraints
    {
        tether
        {
            type            linearSpring;
            body            floatingObject;
            anchor          (0.5 0.3 0.35);
            refAttachmentPt (0.5 0.45 0.35);
            stiffness       20;
            damping         1;
            restLength      0.15;
        }
    }
"""


def make(base, case, density, end_time, coupling, relaxation=0.7,
         outer=3, tolerance=1e-2, max_outer=10, tether=False):
    """A copy of the meshed tutorial in case.

    coupling: "stock" (rigidBodyMotion, accelerationRelaxation relaxation,
    outer correctors) or "addedMass" (addedMassRigidBodyMotion, at most
    max_outer correctors, ended at a coupling residual below tolerance;
    with tolerance None, outer correctors each step). tether: add TETHER.
    """
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(base, case, ignore=shutil.ignore_patterns("log.*"))
    dyn = os.path.join(case, "constant", "dynamicMeshDict")
    substitute(dyn, r"^(\s*rho\s+)500;", rf"\g<1>{density};")
    fvs = os.path.join(case, "system", "fvSolution")
    if tether:
        substitute(dyn, r"^(\s*bodies\s*\n)", TETHER + r"\n\1")
    if coupling == "stock":
        substitute(dyn, r"accelerationRelaxation\s+[0-9.]+;",
            f"accelerationRelaxation {relaxation};")
        substitute(fvs, r"nOuterCorrectors\s+\d+;", f"nOuterCorrectors    {outer};")
    elif coupling == "addedMass":
        substitute(dyn, r"motionSolverLibs\s+\(rigidBodyMeshMotion\);",
            "motionSolverLibs   (rigidBodyMeshMotion foamFmiRigidBodyCoupling);")
        substitute(dyn, r"motionSolver\s+rigidBodyMotion;",
            "motionSolver       addedMassRigidBodyMotion;")
        substitute(dyn, r"rigidBodyMotionCoeffs", "addedMassRigidBodyMotionCoeffs")
        substitute(dyn, r"^\s*accelerationRelaxation\s+[0-9.]+;\n", "")
        if tolerance is None:
            substitute(fvs, r"nOuterCorrectors\s+\d+;",
                f"nOuterCorrectors    {outer};")
        else:
            substitute(fvs, r"nOuterCorrectors\s+\d+;",
                f"nOuterCorrectors    {max_outer};\n"
                "    residualControl\n    {\n"
                f"        rigidBodyCoupling {{ tolerance {tolerance};"
                " relTol 0; }\n    }")
    else:
        raise ValueError(coupling)
    cd = os.path.join(case, "system", "controlDict")
    substitute(cd, r"^endTime\s+[0-9.]+;", f"endTime         {end_time};")
    substitute(cd, r"^writeInterval\s+[0-9.]+;", f"writeInterval   {end_time};")
    return case


def solve(case, solver="interFoamAliasSafe"):
    """Run the solver (one CFD job at a time on this machine); never raises
    on a failed run: the log tells how far it got."""
    env = dict(os.environ, FOAM_SIGFPE="true")
    with open(os.path.join(case, "log.solver"), "w") as out:
        subprocess.run(["flock", LOCK, solver], cwd=case, stdout=out,
                       stderr=subprocess.STDOUT, env=env)
    return parse(os.path.join(case, "log.solver"))


def parse(log):
    """What a run's log says: steps, outer correctors, end, CPU, motion."""
    times, ys, pitches = [], [], []
    steps = correctors = 0
    cpu = 0.0
    ended = False
    residuals = []   # per step: the coupling residuals of its correctors
    newton = []      # per corrector: Newton iterations and final residual
    converged = []   # per step: PIMPLE ended it by residualControl
    with open(log) as f:
        for line in f:
            if line.startswith("Time = "):
                steps += 1
                times.append(float(line.split()[2]))
                residuals.append([])
                converged.append(False)
                ys.append(None)
                pitches.append(None)
            elif line.startswith("Rigid-body motion of the"):
                correctors += 1
            elif "coupling residual" in line:
                residuals[-1].append(float(re.search(
                    r"coupling residual ([-+0-9.eE]+)", line).group(1)))
                m = re.search(r"Newton iterations (\d+) \(residual"
                              r" ([-+0-9.eE]+)\)", line)
                if m:
                    newton.append((int(m.group(1)), float(m.group(2))))
            elif line.startswith("PIMPLE: converged in"):
                converged[-1] = True
            elif line.strip().startswith("Centre of rotation:"):
                # the step's last solve: sway y [m]
                ys[-1] = float(line.split("(")[1].split()[1])
            elif line.strip().startswith("Orientation:"):
                # sine of the pitch: the (0, 2) entry of the rotation tensor
                pitches[-1] = float(line.split("(")[1].split()[2])
            elif line.startswith("ExecutionTime"):
                cpu = float(line.split()[2])
            elif line.strip() == "End":
                ended = True
    return {"steps": steps, "correctors": correctors, "time": times[-1]
            if times else 0.0, "cpu": cpu, "ended": ended, "y": ys,
            "pitch": pitches, "residuals": residuals, "converged": converged,
            "newton": newton,
            "times": times}


def compare(a, b):
    """Largest difference of sway and pitch sine between two runs, at the
    times of a (b linearly interpolated)."""
    def at(r, key, t):
        ts, vs = r["times"], r[key]
        for i in range(1, len(ts)):
            if ts[i] >= t:
                w = (t - ts[i-1])/(ts[i] - ts[i-1])
                return vs[i-1] + w*(vs[i] - vs[i-1])
        return vs[-1]
    dy = max(abs(y - at(b, "y", t)) for t, y in zip(a["times"], a["y"])
             if y is not None)
    dp = max(abs(p - at(b, "pitch", t)) for t, p in
             zip(a["times"], a["pitch"]) if p is not None)
    span = max(a["y"]) - min(a["y"])
    return dy, dp, span

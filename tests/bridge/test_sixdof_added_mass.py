"""The added-mass coupling under sixDoFRigidBodyMotion reads its entries as
addedMassRigidBodyMotion does, and carries the added mass through a
restart, without a CFD solver.

addedMassSixDoFRigidBodyMotion (the motion solver, one body), moved by
moveDynamicMesh in test mode (gravity only, no fluid loads) on the box of
test_added_mass_entries (2 x 2 x 2 cells, the bottom the body's patch):

  - OpenFOAM's sixDoFRigidBodyMotion entries and the coupling run; an
    unknown coupling entry, a misspelt keyword, a coupling entry out of its
    place, a bad value and an accelerationRelaxation with the added mass
    stop the run when the solver is built, with a FatalIOError naming the
    entry;
  - a restart reads the added mass from uniform/sixDoFRigidBodyMotionState
    and writes it on unchanged (test mode estimates none: the matrix must
    come from the state, digit for digit); a matrix of another size, and a
    state without the added mass when the coupling is on, stop the restart
    naming the entry;
  - the state carries the last step's mean velocities and their change
    (the coupling's accelerations), analytic for the body falling from
    rest: a restart goes on from them as the uninterrupted run does, a
    state without them (written before they were kept) restarts from the
    state's velocities with a note in the log, one with some of them only
    stops naming the one missing.

addedMassSixDoFRigidBodyDisplacement (the point-patch condition of
0/pointDisplacement, mesh moved by displacementLaplacian) is built by
moveDynamicMesh with no time step (it needs the fluid's loads to move): its
entries are accepted, a written (nonuniform) value is read as a restart
reads it, and the same bad entries stop it. A restart from a field file
whose patch entry lacks the added mass (the coupling on) or the motion's
state stops with a FatalIOError naming the file, the patch, the entry and
what was expected; one without the mean velocities goes on with a note.
"""
import os
import re
import shutil
import sys

from foamfmi.bridgecase import foam_file
from test_added_mass_entries import make_case, ran, refused, run, run_cases, run_checks

SOLVER = "addedMassSixDoFRigidBodyMotion"
STATE = os.path.join("uniform", "sixDoFRigidBodyMotionState")
VALID_COUPLING = "addedMass, pressure, residual, addedMassInterval, maxIter, tolerance"

BODY = """
    mass 1;
    centreOfMass (0.5 0.5 0);
    momentOfInertia (0.1 0.1 0.1);
    report off;
    solver { type Newmark; }
"""


def solver_dict(coeffs_extra="", coupling="coupling { addedMass on; maxIter 10; }", test="yes"):
    """dynamicMeshDict of the motion solver in test mode."""
    return f"""
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs (sixDoFRigidBodyMotion foamFmiRigidBodyCoupling);
motionSolver {SOLVER};
{SOLVER}Coeffs
{{
    patches (body);
    innerDistance 0.1;
    outerDistance 0.6;
    test {test};
    rho rhoInf;
    rhoInf 1000;
    g (0 0 -9.81);
    accelerationDamping 1;
    {BODY}
    {coupling}
    {coeffs_extra}
}}
"""


PATCH_MESH_DICT = """
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs (fvMotionSolvers);
motionSolver displacementLaplacian;
displacementLaplacianCoeffs { diffusivity uniform; }
"""


def patch_displacement(entries="coupling { addedMassInterval 5; }"):
    """0/pointDisplacement with the body's point-patch condition."""
    return f"""
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{{
    body
    {{
        type addedMassSixDoFRigidBodyDisplacement;
        rho rhoInf;
        rhoInf 1000;
        {BODY}
        {entries}
        value uniform (0 0 0);
    }}
    walls {{ type fixedValue; value uniform (0 0 0); }}
}}
"""


# The body falls from rest under g alone (test mode). Its state starts
# with no acceleration, so Newmark (beta 1/4, gamma 1/2) moves it by
# g dt^2/4 in the first step of dt, to the velocity g dt/2, and by
# g dt^2 in the second: mean velocities g dt/4 and g dt, changes per dt
# g/4 from rest and 3 g/4. A restart that takes the state's velocity
# (g dt/2) for the first step's mean velocity gets g/2 in the second step.
G = -9.81
DT = 0.01
MEANS = ("meanAngularVelocity", "meanVelocity", "meanAngularAcceleration",
         "meanAcceleration")


def close(values, expected):
    """Equal to 1e-9 of the largest magnitude: the state is written with
    12 digits, and a restart's mean acceleration divides the difference of
    two such mean velocities (0.1 m/s, rounded by 1e-13) by dt 0.01 s,
    1e-11 of 7 m/s^2; the restart without the means is 1/3 off."""
    scale = max(max(abs(e) for e in expected), 1e-300)
    return values is not None and len(values) == len(expected) and all(
        abs(v - e) <= 1e-9 * scale for v, e in zip(values, expected))


def means_check(path, velocity, acceleration):
    """(ok, detail): the state file's mean velocities and accelerations are
    those of the fall: the last step's mean velocity and its change per dt
    as given (z) [m/s, m/s^2]."""
    with open(path) as f:
        text = f.read()
    got = {key: state_entry(text, key) for key in MEANS}
    expected = {"meanAngularVelocity": [0, 0, 0], "meanVelocity": [0, 0, velocity],
                "meanAngularAcceleration": [0, 0, 0], "meanAcceleration": [0, 0, acceleration]}
    ok = all(close(got[key], expected[key]) for key in MEANS)
    return ok, "" if ok else f", {path} carries {got}, expected {expected}"


def matrix(n, scale):
    """An n x n matrix in OpenFOAM's form, distinct digits in every place."""
    rows = [" ".join(f"{scale * (1 + i) + 0.001 * j:.6g}" for j in range(n)) for i in range(n)]
    return f"{n} {n}(" + " ".join(f"({r})" for r in rows) + ")"


def state_entry(text, key):
    """The numbers of entry key in a state file (a matrix: its size, then its
    rows), or None."""
    start = text.find(key + " ")
    if start < 0:
        return None
    body = text[start + len(key):text.index(";", start)]
    return [float(x) for x in re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", body)]


def restart_checks(work):
    """(name, ok, detail) of restarts from the state of time 0.01."""
    results = []
    full = make_case(work, "full", solver_dict())
    control = os.path.join(full, "system", "controlDict")
    with open(control) as f:
        text = f.read()
    with open(control, "w") as f:
        f.write(text.replace("writeInterval 100;", "writeInterval 1;"))
    code, log = run(full)
    ok, detail = ran(code, log)
    results.append(("run to restart from", ok and os.path.exists(os.path.join(full, "0.01", STATE)),
                    detail))
    if ok:
        # the first step from rest, then the second
        first, more = means_check(os.path.join(full, "0.01", STATE), 0.25 * G * DT, 0.25 * G)
        second, more2 = means_check(os.path.join(full, "0.02", STATE), G * DT, 0.75 * G)
        results.append(("the state's mean velocities and accelerations", first and second,
                        detail + more + more2))

    def restart(name, added, mesh_dict=solver_dict(), drop=()):
        case = os.path.join(work, name)
        shutil.copytree(full, case)
        shutil.rmtree(os.path.join(case, "0.02"))
        path = os.path.join(case, "0.01", STATE)
        with open(path) as f:
            state = f.read()
        for key in drop:
            state = re.sub(rf"^\s*{key}\s[^;]*;\n", "", state, flags=re.M)
        with open(path, "w") as f:
            f.write(state.replace("// *", added + "\n// *", 1) if added else state)
        with open(os.path.join(case, "constant", "dynamicMeshDict"), "w") as f:
            f.write(foam_file("dynamicMeshDict", mesh_dict))
        with open(os.path.join(case, "system", "controlDict")) as f:
            text = f.read()
        with open(os.path.join(case, "system", "controlDict"), "w") as f:
            f.write(text.replace("startFrom startTime;", "startFrom latestTime;"))
        code, log = run(case)
        return case, code, log

    body_matrix = matrix(6, 10.0)
    case, code, log = restart("addedMassBody", f"addedMassBody {body_matrix};")
    ok, detail = ran(code, log)
    written = os.path.join(case, "0.02", STATE)
    if ok:
        with open(written) as f:
            again = state_entry(f.read(), "addedMassBody")
        expected = state_entry(f"addedMassBody {body_matrix};", "addedMassBody")
        # test mode estimates nothing: the state's matrix goes on unchanged,
        # every digit (written with writePrecision 12, read back exactly)
        same = again == expected
        ok = same
        detail += "" if same else f", 0.02 carries addedMassBody {again}"
    results.append(("restart goes on with the state's added mass", ok, detail))
    if os.path.exists(written):
        # as the uninterrupted run: the second step's change 3 g/4, no note
        ok, more = means_check(written, G * DT, 0.75 * G)
        ok = ok and "has no meanAngularVelocity" not in log
        results.append(("restart goes on from the state's mean velocities", ok,
                        f"exit code {code}" + more))

    case, code, log = restart("withoutMeans", "", drop=MEANS)
    ok, detail = ran(code, log)
    note = "has no meanAngularVelocity, meanVelocity" in log and "restart is not exact" in log
    if ok:
        ok, more = means_check(os.path.join(case, "0.02", STATE), G * DT, 0.5 * G)
        ok = ok and note
        detail += more + ("" if note else ", no note in the log:\n" + log[-2500:])
    results.append(("a state without the mean velocities (before they were kept)", ok, detail))

    _, code, log = restart("someMeans", "", drop=MEANS[:1])
    results.append(("a state with some of the mean velocities",
                    *refused(code, log, ["'meanAngularVelocity'", STATE])))

    _, code, log = restart("wrongSize", f"addedMassBody {matrix(12, 1.0)};")
    results.append(("a state's added mass of another size",
                    *refused(code, log, ["addedMassBody' has 12 rows, 6 expected"])))

    _, code, log = restart("withoutAddedMass", "", solver_dict(test="no"))
    ok = code != 0 and "lacks its entry 'addedMass'" in log
    results.append(("coupling on, state without the added mass", ok,
                    f"exit code {code}" + ("" if ok else "\n" + log[-2500:])))
    return results


RESTART_STATE = {
    "centreOfRotation": "(0.5 0.5 -0.000245)", "orientation": "(1 0 0 0 1 0 0 0 1)",
    "velocity": "(0 0 -0.049)", "acceleration": "(0 0 -9.81)",
    "angularMomentum": "(0 0 0)", "torque": "(0 0 0)", "addedMass": matrix(6, 1.0),
    "meanAngularVelocity": "(0 0 0)", "meanVelocity": "(0 0 -0.0245)",
    "meanAngularAcceleration": "(0 0 0)", "meanAcceleration": "(0 0 -2.45)",
}


def patch_restart_checks(work):
    """(name, ok, detail) of point-patch restarts from a time 0.01 whose
    field file has the entries of RESTART_STATE but those dropped."""
    libs = 'libs ("libfoamFmiRigidBodyCoupling.so");\n'

    def restart(name, drop=(), coupling="coupling { addedMassInterval 5; }"):
        entries = " ".join(f"{k} {v};" for k, v in RESTART_STATE.items() if k not in drop)
        case = make_case(work, name, PATCH_MESH_DICT, patch_displacement(coupling),
                         end_time="0.01", libs=libs)
        os.makedirs(os.path.join(case, "0.01"))
        with open(os.path.join(case, "0", "pointDisplacement")) as f:
            text = f.read()
        with open(os.path.join(case, "0.01", "pointDisplacement"), "w") as f:
            value = "value uniform (0 0 0);\n"
            f.write(text.replace(value, entries + "\n" + value, 1))
        control = os.path.join(case, "system", "controlDict")
        with open(control) as f:
            text = f.read()
        with open(control, "w") as f:
            f.write(text.replace("startFrom startTime;", "startFrom latestTime;"))
        return run(case)

    field = os.path.join("0.01", "pointDisplacement")
    note = "has no meanAngularVelocity"
    results = []
    code, log = restart("patchRestart")
    ok, detail = ran(code, log)
    results.append(("patchRestart", ok and note not in log, detail))
    code, log = restart("patchRestartWithoutMeans", drop=MEANS)
    ok, detail = ran(code, log)
    ok = ok and note in log and field in log
    results.append(("patchRestartWithoutMeans (a note)", ok,
                    detail + ("" if ok else "\n" + log[-2500:])))
    code, log = restart("patchRestartWithoutAddedMass", drop=("addedMass",))
    results.append(("patchRestartWithoutAddedMass", *refused(code, log, [
        field, "patch 'body' lacks 'addedMass'", "the added mass in use, a 6 x 6 matrix"])))
    code, log = restart("patchRestartWithoutOrientation", drop=("orientation",))
    results.append(("patchRestartWithoutOrientation", *refused(code, log, [
        field, "patch 'body' lacks 'orientation'",
        "the motion's state (centreOfRotation, orientation, velocity"])))
    code, log = restart("patchRestartAddedMassOff", drop=("addedMass",),
                        coupling="coupling { addedMass off; }")
    results.append(("patchRestartAddedMassOff (no added mass needed)", *ran(code, log)))
    return results


def main():
    libs = 'libs ("libfoamFmiRigidBodyCoupling.so");\n'
    solver_cases = [
        ("valid", solver_dict(), None),
        ("userEntriesForExpansion", solver_dict(coeffs_extra="springParameters { k 10; }"), None),
        ("couplingTypos", solver_dict(coupling="coupling { maxIters 0; tolerence 7; }"),
         [f"{SOLVER}: unknown coupling entry 'maxIters'", VALID_COUPLING]),
        ("misspeltCoupling", solver_dict(coupling="couplng { addedMass on; }"),
         ["unknown entry 'couplng'", "OpenFOAM's sixDoFRigidBodyMotion's", "innerDistance",
          VALID_COUPLING]),
        ("misspeltOpenFoamEntry", solver_dict(coeffs_extra="momentOfInertai (1 1 1);"),
         ["unknown entry 'momentOfInertai'", "did you mean 'momentOfInertia'"]),
        ("couplingEntryAtTopLevel", solver_dict(coeffs_extra="addedMassInterval 5;"),
         ["unknown entry 'addedMassInterval'", "belongs in the coupling sub-dictionary"]),
        ("maxIterZero", solver_dict(coupling="coupling { maxIter 0; }"),
         ["maxIter = 0", "at least one Newton iteration"]),
        ("wordTolerance", solver_dict(coupling="coupling { tolerance small; }"),
         ["coupling entry 'tolerance' expects a number, got 'small'"]),
        ("relaxation", solver_dict(coeffs_extra="accelerationRelaxation 0.5;"),
         ["accelerationRelaxation 0.5 with the added-mass coupling"]),
    ]
    patch_cases = [
        ("patchValid", patch_displacement(), None),
        ("patchCouplingTypos", patch_displacement("coupling { addedMassInteval 5; }"),
         ["unknown coupling entry 'addedMassInteval'", VALID_COUPLING]),
        ("patchMisspelt", patch_displacement("momentOfInertai (1 1 1);"),
         ["unknown entry 'momentOfInertai'", "did you mean 'momentOfInertia'",
          "OpenFOAM's sixDoFRigidBodyDisplacement's"]),
        # the means the condition writes are its entries too
        ("patchMisspeltMean", patch_displacement("meanVelocty (0 0 0);"),
         ["unknown entry 'meanVelocty'", "did you mean 'meanVelocity'"]),
        ("patchRelaxation", patch_displacement("accelerationRelaxation 0.7;"),
         ["accelerationRelaxation 0.7 with the added-mass coupling"]),
        ("patchTolerance", patch_displacement("coupling { tolerance 2; }"),
         ["tolerance = 2", "must be in (0, 1)"]),
        # a restart: the value as a written time holds it, one displacement
        # per point of the patch (3 x 3), read once
        ("patchWrittenValue", patch_displacement().replace(
            "value uniform (0 0 0);",
            "value nonuniform List<vector> 9(" + "".join(
                f"(0 0 {0.001 * (i + 1)})" for i in range(9)) + ");", 1), None),
    ]

    def checks(work):
        # patch cases without a time step: the condition is built, and moves
        # only with a fluid
        return (run_cases(solver_cases, lambda name, text: make_case(work, name, text))
                + run_cases(patch_cases, lambda name, text: make_case(
                    work, name, PATCH_MESH_DICT, text, end_time="0", libs=libs))
                + restart_checks(work)
                + patch_restart_checks(work))

    return run_checks("sixDoFAddedMass.", checks)


if __name__ == "__main__":
    sys.exit(main())

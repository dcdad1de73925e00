#!/usr/bin/env python3
"""addedMassRigidBodyMotion's added-mass matrix turns with the bodies
between two estimates, and a restart goes on with the estimate in the
body's axes.

A box of 0.4 x 0.2 x 0.2 m (8 x 4 x 4 cells cut out of a 1.2 x 1.2 x 0.9 m
tank of 24 x 24 x 18 cells, water everywhere, p_rgh = 0 on the top) on a
joint Rz about the point 0.1 m behind its centre, the body's origin (so
that M couples the yaw moment with sway, M(2,4) = 1.6 kg m: a rotation by
+90 degrees and one by -90 degrees give different matrices).
interFoamAliasSafe, one to three steps of 1 ms, the state written with 17
digits at every step. R is the body's orientation (body to global axes)
at the start of a step, from the written q; T = blockdiag(R, R).

  - "turning": the box spins at 50 rad/s (0.05 rad a step), an estimate
    every 3 steps. The matrix used at step 2 (the state's addedMass) is
    T M_body T^T of the step-1 estimate, and step 3's new estimate is
    kept as M_body = T^T M T, each to rounding (1e-12 of the largest
    entry); step 3's estimate in body axes, on the mesh morphed by
    0.1 rad, matches step 1's within MORPH_TOLERANCE, 5e-3 of the largest
    entry: the morphed cells (non-orthogonal up to 15 degrees, none
    before) change the discretisation, by 8e-4 measured.
  - "rotated": the same box built rotated by +90 degrees about z (the cells
    cut out at the box's place after the rotation, the body's transform
    rotated so): the estimate in body axes matches that of the box
    unrotated within SOLVER_TOLERANCE, 1e-9 of the largest entry. The
    tank is square and the grid maps onto itself under the rotation, so
    both estimates solve the same discrete problem, numbered otherwise:
    they differ by the pressure solver's error only (p_rgh solved to a
    residual of 1e-12; 6e-15 measured), not by the discretisation's. The
    water's shape is the same in both (no free surface moves: the top is
    p_rgh = 0 at 0.35 m from the box in both). (The morphing of
    rigidBodyMotion cannot turn this mesh by 90 degrees: with
    outerDistance 0.3 m, 190 cells turn inside out.) In global axes the
    two differ by O(1): the matrix must follow the body.
  - restarts of "rotated" after its step 1: with the unrotated box's
    estimate as its state's addedMassBody, the matrix used at step 2 is
    T M_body T^T with R the +90-degree rotation, to rounding; from a state
    file without addedMassBody (as written before), the state's addedMass
    is taken as the matrix in the axes of the state's orientation and used
    unchanged; an addedMassBody of the wrong size is a FatalIOError.
"""

import math
import os
import re
import shutil
import subprocess
import sys

from foamfmi import cli
from foamfmi.bridgecase import foam_file

DT = 0.001
STATE = os.path.join("uniform", "rigidBodyMotionState")
ROUNDING = 1e-12
SOLVER_TOLERANCE = 1e-9
MORPH_TOLERANCE = 5e-3
# Body length: rows and columns of rotation scaled by 1/L, so that every
# entry of S M S is a mass [kg]
LENGTH = 0.4

BLOCK_MESH = """
vertices ((-0.6 -0.6 -0.45) (0.6 -0.6 -0.45) (0.6 0.6 -0.45) (-0.6 0.6 -0.45)
          (-0.6 -0.6 0.45) (0.6 -0.6 0.45) (0.6 0.6 0.45) (-0.6 0.6 0.45));
blocks (hex (0 1 2 3 4 5 6 7) (24 24 18) simpleGrading (1 1 1));
boundary
(
    walls { type wall; faces ((0 3 2 1) (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
    atmosphere { type patch; faces ((4 5 6 7)); }
    body { type wall; faces (); }
);
"""

# The cells of the box, unrotated and rotated by +90 degrees about z
BOX = {False: "(-0.1 -0.1 -0.1) (0.3 0.1 0.1)",
       True: "(-0.1 -0.1 -0.1) (0.1 0.3 0.1)"}

TOPO_SET = """
actions
(
    {{ name c0; type cellSet; action new; source boxToCell; box {box}; }}
    {{ name c0; type cellSet; action invert; }}
);
"""

CONTROL = """
application interFoamAliasSafe;
startFrom latestTime; startTime 0; stopAt endTime; endTime {end}; deltaT {dt};
writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 17;
writeCompression off; timeFormat general; timePrecision 6;
runTimeModifiable false; adjustTimeStep no; maxCo 100; maxAlphaCo 100;
"""

SCHEMES = """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    div(rhoPhi,U) Gauss upwind;
    div(phi,alpha) Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
"""

# p_rgh converged to 1e-12 (relTol 0): the estimates' own solver error
# stays far below the differences measured
SOLUTION = """
solvers
{
    "alpha.water.*" { nAlphaCorr 1; nAlphaSubCycles 1; cAlpha 1; MULESCorr yes;
        nLimiterIter 3; solver smoothSolver; smoother symGaussSeidel;
        tolerance 1e-8; relTol 0; }
    "pcorr.*" { solver PCG; preconditioner DIC; tolerance 1e-6; relTol 0; }
    p_rgh { solver PCG; preconditioner DIC; tolerance 1e-12; relTol 0; }
    p_rghFinal { $p_rgh; }
    "U.*" { solver smoothSolver; smoother GaussSeidel; tolerance 1e-8; relTol 0; }
}
PIMPLE
{
    momentumPredictor no; nOuterCorrectors 2; nCorrectors 1;
    nNonOrthogonalCorrectors 0; correctPhi yes; moveMeshOuterCorrectors no;
}
"""

CONSTANT = {
    "g": "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n",
    "transportProperties": """
phases (water air);
water { transportModel Newtonian; nu 1e-06; rho 1000; }
air { transportModel Newtonian; nu 1.48e-05; rho 1; }
sigma 0;
""",
    "turbulenceProperties": "simulationType laminar;\n",
}

# A heavy body (1e4 kg, 1e4 kg m^2): the water hardly changes its spin
DYNAMIC_MESH = """
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs (rigidBodyMeshMotion foamFmiRigidBodyCoupling);
motionSolver addedMassRigidBodyMotion;
addedMassRigidBodyMotionCoeffs
{{
    report on;
    solver {{ type Newmark; }}
    rho rho;
    q (0);
    qDot ({spin});
    bodies
    {{
        box
        {{
            type rigidBody;
            parent root;
            mass 1e4;
            centreOfMass (0.1 0 0);
            inertia (1e4 0 0 1e4 0 1e4);
            transform {transform} (0 0 0);
            joint {{ type Rz; }}
            patches (body);
            innerDistance 0.02;
            outerDistance 0.3;
        }}
    }}
    coupling {{ addedMassInterval 3; }}
}}
"""

# Global to body axes of the body's transform (OpenFOAM's E): +90 degrees
TRANSFORM = {False: "(1 0 0 0 1 0 0 0 1)", True: "(0 1 0 -1 0 0 0 0 1)"}

def with_value(condition, value="(0 0 0)"):
    """A boundary condition of type `condition` with its uniform value."""
    return f"type {condition}; value uniform {value};"


FIELDS = {
    "U": ("volVectorField", "[0 1 -1 0 0 0 0]", "(0 0 0)", {
        "walls": "type noSlip;",
        "body": with_value("movingWallVelocity"),
        "atmosphere": with_value("pressureInletOutletVelocity")}),
    "p_rgh": ("volScalarField", "[1 -1 -2 0 0 0 0]", "0", {
        "walls": "type fixedFluxPressure;",
        "body": "type fixedFluxPressure;",
        "atmosphere": "type totalPressure; p0 uniform 0;"}),
    "alpha.water": ("volScalarField", "[0 0 0 0 0 0 0]", "1", {
        "walls": "type zeroGradient;",
        "body": "type zeroGradient;",
        "atmosphere": "type inletOutlet; inletValue uniform 1; value uniform 1;"}),
    "pointDisplacement": ("pointVectorField", "[0 1 0 0 0 0 0]", "(0 0 0)", {
        "walls": with_value("fixedValue"),
        "atmosphere": with_value("fixedValue"),
        "body": with_value("calculated")}),
}


def fail(message):
    print(f"FAIL [addedMassRotation]: {message}")
    sys.exit(1)


def write(path, name, body, cls="dictionary"):
    with open(path, "w") as f:
        f.write(foam_file(name, body).replace("class dictionary", "class " + cls))


def run(case, *command):
    """Exit code and log of a command run in the case."""
    result = subprocess.run(command, cwd=case, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(case, "log." + command[0]), "a") as f:
        f.write(result.stdout)
    return result.returncode, result.stdout


def make(case, rotated, spin, end_steps):
    """The tank with the box (rotated by +90 degrees about z or not),
    meshed, spinning at spin rad/s, to end_steps steps."""
    for folder in ("system", "constant"):
        os.makedirs(os.path.join(case, folder))
    system = {"blockMeshDict": BLOCK_MESH,
              "topoSetDict": TOPO_SET.format(box=BOX[rotated]),
              "controlDict": CONTROL.format(end=end_steps*DT, dt=DT),
              "fvSchemes": SCHEMES, "fvSolution": SOLUTION}
    for name, body in system.items():
        write(os.path.join(case, "system", name), name, body)
    constant = dict(CONSTANT, dynamicMeshDict=DYNAMIC_MESH.format(
        spin=spin, transform=TRANSFORM[rotated]))
    for name, body in constant.items():
        write(os.path.join(case, "constant", name), name, body)
    for command in (["blockMesh"], ["topoSet"],
                    ["subsetMesh", "-overwrite", "c0", "-patch", "body"]):
        code, log = run(case, *command)
        if code:
            fail(f"{command[0]} failed in {case}:\n{log[-2000:]}")
    # The fields after subsetMesh, which would make the new patch's empty
    os.makedirs(os.path.join(case, "0"))
    for name, (cls, dims, value, patches) in FIELDS.items():
        boundary = "".join(f"    {p} {{ {bc} }}\n" for p, bc in patches.items())
        write(os.path.join(case, "0", name), name,
              f"dimensions {dims};\ninternalField uniform {value};\n"
              f"boundaryField\n{{\n{boundary}}}\n", cls)
    return case


def solve(case):
    code, log = run(case, "interFoamAliasSafe")
    if code:
        fail(f"interFoamAliasSafe failed in {case}:\n{log[-3000:]}")
    return log


def time_name(step):
    return f"{step*DT:g}"


def state_text(case, step):
    with open(os.path.join(case, time_name(step), STATE)) as f:
        return f.read()


def matrix(text, key):
    """The 6 x 6 matrix entry key of a state file's text, or None."""
    m = re.search(rf"^{key}\s+6\s+6\s*\((.*?)\)\s*\)\s*;", text, re.M | re.S)
    if not m:
        return None
    values = [float(v) for v in re.findall(r"[-+0-9.eE]+", m.group(1))]
    if len(values) != 36:
        fail(f"entry {key} holds {len(values)} numbers, not 36")
    return [values[6*i:6*i + 6] for i in range(6)]


def angle(text):
    """The joint angle q of a state file's text [rad]."""
    return float(re.search(r"^q\s+1\s*\(\s*(\S+)\s*\)", text, re.M).group(1))


def rotation(theta):
    """Body to global axes of a rotation by theta about z."""
    c, s = math.cos(theta), math.sin(theta)
    return [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]


def transposed(a):
    return [list(row) for row in zip(*a)]


def rotate(M, R):
    """T M T^T, T = blockdiag(R, R)."""
    T = [[0.0]*6 for _ in range(6)]
    for b in (0, 3):
        for i in range(3):
            for j in range(3):
                T[b + i][b + j] = R[i][j]
    TM = [[sum(T[i][k]*M[k][j] for k in range(6)) for j in range(6)]
          for i in range(6)]
    return [[sum(TM[i][k]*T[j][k] for k in range(6)) for j in range(6)]
            for i in range(6)]


def scaled_difference(A, B):
    """max |S (A - B) S| / max |S B S|, S = diag(1/L, 1/L, 1/L, 1, 1, 1)."""
    s = [1/LENGTH]*3 + [1.0]*3
    diff = max(abs(s[i]*(A[i][j] - B[i][j])*s[j])
               for i in range(6) for j in range(6))
    size = max(abs(s[i]*B[i][j]*s[j]) for i in range(6) for j in range(6))
    return diff/size


def entries(M):
    """The entries the report prints: yaw, surge, sway, yaw-sway, yaw-surge."""
    return (f"M(2,2) {M[2][2]:.6g} kg m^2, M(3,3) {M[3][3]:.6g} kg,"
            f" M(4,4) {M[4][4]:.6g} kg, M(2,4) {M[2][4]:.6g} kg m,"
            f" M(2,3) {M[2][3]:.6g} kg m")


def check(difference, bound, what):
    print(f"{what}: {difference:.3g} (bound {bound:g})")
    if not difference <= bound:
        fail(f"{what}: {difference:.3g} above {bound:g}")


def restart(base, case, state_edit):
    """A copy of the rotated case after its step 1, its state edited, run
    to step 2: exit code and log."""
    shutil.copytree(base, case)
    path = os.path.join(case, time_name(1), STATE)
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(state_edit(text))
    control = os.path.join(case, "system", "controlDict")
    with open(control) as f:
        text = f.read()
    with open(control, "w") as f:
        f.write(text.replace(f"endTime {DT:g};", f"endTime {2*DT:g};"))
    return run(case, "interFoamAliasSafe")


def replace_entry(text, key, value):
    """The state text with entry key's value replaced (value None: removed)."""
    pattern = rf"^{key}\s+6\s+6\s*\(.*?\)\s*\)\s*;\n"
    new, n = re.subn(pattern, "" if value is None else f"{key} {value};\n",
                     text, flags=re.M | re.S)
    if n != 1:
        fail(f"no entry {key} in the state")
    return new


def as_entry(M):
    rows = " ".join("(" + " ".join(repr(v) for v in row) + ")" for row in M)
    return f"6 6 ({rows})"


def main(argv):
    p = cli.parser("addedMassRotation.py", __doc__)
    cli.add_keep(p)
    with cli.scratch("addedMassRotation.", p.parse_args(argv).keep) as work:
        # Turning between two estimates, without a restart
        turning = make(os.path.join(work, "turning"), False, 50, 3)
        solve(turning)
        s1, s2, s3 = (state_text(turning, n) for n in (1, 2, 3))
        body1 = matrix(s1, "addedMassBody")
        if body1 is None or matrix(s1, "addedMass") is None:
            fail("the state of step 1 lacks addedMass or addedMassBody")
        print(f"step 1, estimate at q = 0: {entries(body1)}")
        R1, R2 = rotation(angle(s1)), rotation(angle(s2))
        used2 = matrix(s2, "addedMass")
        print(f"step 2, q = {angle(s1):.4g} rad at its start: {entries(used2)}")
        check(scaled_difference(used2, rotate(body1, R1)), ROUNDING,
              "turning, step 2: the matrix used against T M_body T^T")
        check(scaled_difference(matrix(s2, "addedMassBody"), body1), 0,
              "turning, step 2: M_body kept")
        body3 = matrix(s3, "addedMassBody")
        check(scaled_difference(body3, rotate(matrix(s3, "addedMass"),
                                              transposed(R2))),
              ROUNDING, "turning, step 3: the new estimate against T^T M T")
        print(f"step 3, estimate at q = {angle(s2):.4g} rad, body axes:"
              f" {entries(body3)}")
        check(scaled_difference(body3, body1), MORPH_TOLERANCE,
              f"turning: estimate on the mesh morphed by {angle(s2):.3g} rad"
              " against the first, body axes")

        # The box built rotated by +90 degrees
        rotated = make(os.path.join(work, "rotated"), True, 0, 1)
        solve(rotated)
        r1 = state_text(rotated, 1)
        R = rotation(angle(r1) + math.pi/2)
        body = matrix(r1, "addedMassBody")
        used = matrix(r1, "addedMass")
        print(f"rotated box, estimate, global axes: {entries(used)}")
        print(f"rotated box, estimate, body axes: {entries(body)}")
        check(scaled_difference(body, rotate(used, transposed(R))), ROUNDING,
              "rotated box: M_body against T^T M T")
        check(scaled_difference(body, body1), SOLVER_TOLERANCE,
              "rotated box against unrotated, body axes")
        unfollowed = scaled_difference(used, matrix(s1, "addedMass"))
        print(f"rotated box against unrotated, global axes: {unfollowed:.3g}")
        if unfollowed < 100*SOLVER_TOLERANCE:
            fail("the rotated box's matrix in global axes is that of the"
                 " unrotated box: the test cannot tell a matrix that follows"
                 " the body from one that does not")

        # Restarts: the unrotated box's estimate given to the rotated body
        case = os.path.join(work, "restartRotated")
        code, log = restart(rotated, case, lambda text: replace_entry(
            text, "addedMassBody", as_entry(body1)))
        if code:
            fail(f"the restart with the unrotated estimate failed:\n{log[-3000:]}")
        used = matrix(state_text(case, 2), "addedMass")
        print(f"restart, body turned by +90 degrees, matrix used: {entries(used)}")
        check(scaled_difference(used, rotate(body1, R)), ROUNDING,
              "restart: the matrix used against T M_body T^T, +90 degrees")

        # A state file as written before addedMassBody
        case = os.path.join(work, "restartOld")
        code, log = restart(rotated, case, lambda text: replace_entry(
            text, "addedMassBody", None))
        if code:
            fail(f"the restart without addedMassBody failed:\n{log[-3000:]}")
        s = state_text(case, 2)
        check(scaled_difference(matrix(s, "addedMass"), matrix(r1, "addedMass")),
              ROUNDING, "restart without addedMassBody: the state's addedMass used")
        check(scaled_difference(matrix(s, "addedMassBody"), body), ROUNDING,
              "restart without addedMassBody: M_body from it")

        # A matrix for other bodies
        case = os.path.join(work, "restartWrongSize")
        code, log = restart(rotated, case, lambda text: replace_entry(
            text, "addedMassBody", "3 3 ((1 0 0) (0 1 0) (0 0 1))"))
        expected = "added-mass matrix 'addedMassBody' has 3 rows, 6 expected"
        if code == 0 or "FOAM FATAL IO ERROR" not in log or expected not in log:
            fail(f"an addedMassBody of 3 x 3 did not stop the run naming it:"
                 f"\n{log[-3000:]}")
        print("restart with an addedMassBody of 3 x 3: FatalIOError")
        print("PASS [addedMassRotation]")


if __name__ == "__main__":
    main(sys.argv[1:])

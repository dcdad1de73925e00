"""addedMassRigidBodyMotion reads its dictionary strictly: an unknown
keyword in the coupling sub-dictionary, a misspelt keyword or a coupling
entry out of its place at the coefficients' level, and an entry of the
wrong type, stop the run when the motion solver is built, with a
FatalIOError that names the entry and lists the valid ones or says what is
expected. OpenFOAM's own rigidBodyMotion entries are accepted, and so are
the user's entries for $-expansion at the coefficients' level (the
tutorials keep restraint parameters there). A PIMPLE dictionary of one
outer corrector is warned of: the motion is far from converged there.

Before, `coupling { maxIters 0; tolerence 7; }`, a misspelt `couplng { }`
and a top-level `addedMassInteval 0` were ignored (exit code 0, the
defaults in force), and `coupling 5;` gave only OpenFOAM's "not a
sub-dictionary" warning.

No CFD: a box of 2 x 2 x 2 cells whose bottom is the body's patch, moved by
moveDynamicMesh with the solver in test mode (gravity only, no fluid
loads), two time steps.
"""
import os
import shutil
import subprocess
import sys
import tempfile

from foamfmi.bridgecase import foam_file

BLOCK_MESH = """
vertices ((0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1));
blocks (hex (0 1 2 3 4 5 6 7) (2 2 2) simpleGrading (1 1 1));
boundary
(
    body { type wall; faces ((0 3 2 1)); }
    walls { type wall; faces ((4 5 6 7) (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
);
"""

POINT_DISPLACEMENT = """
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    body { type calculated; value uniform (0 0 0); }
    walls { type fixedValue; value uniform (0 0 0); }
}
"""

CONTROL = """
application moveDynamicMesh;
startFrom startTime; startTime 0; stopAt endTime; endTime 0.02; deltaT 0.01;
writeControl timeStep; writeInterval 100; writeFormat ascii;
writePrecision 12; timePrecision 6; runTimeModifiable false;
"""

SCHEMES = """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
"""


def mesh_dict(coeffs_extra="", coupling="coupling { addedMass on; maxIter 10; tolerance 1e-9; }",
              top_level=""):
    """dynamicMeshDict with OpenFOAM's own rigidBodyMotion entries and the
    given coupling and extra entries."""
    return f"""
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs (rigidBodyMeshMotion foamFmiRigidBodyCoupling);
motionSolver addedMassRigidBodyMotion;
rhoInf 1000;    // where OpenFOAM's rigidBodyMotion reads it
{top_level}
addedMassRigidBodyMotionCoeffs
{{
    test yes;
    nIter 1;
    report off;
    rho rhoInf;
    rhoInf 1000;
    g (0 0 -9.81);
    accelerationDamping 1;
    solver {{ type Newmark; }}
    bodies
    {{
        box
        {{
            type rigidBody;
            parent root;
            mass 1;
            centreOfMass (0 0 0);
            inertia (0.1 0 0 0.1 0 0.1);
            transform (1 0 0 0 1 0 0 0 1) (0.5 0.5 0);
            joint {{ type Pz; }}
            patches (body);
            innerDistance 0.1;
            outerDistance 0.6;
        }}
    }}
    {coupling}
    {coeffs_extra}
}}
"""


def make_case(work, name, dynamic_mesh_dict, displacement=POINT_DISPLACEMENT,
              end_time="0.02", libs="", control=CONTROL, block_mesh=BLOCK_MESH):
    """The box in work/name, meshed: dynamicMeshDict, 0/pointDisplacement,
    the end time and the controlDict's libs entry given (another
    controlDict's and blockMeshDict's text: control, block_mesh)."""
    case = os.path.join(work, name)
    for folder in ("system", "constant", "0"):
        os.makedirs(os.path.join(case, folder))
    control = control.replace("endTime 0.02;", f"endTime {end_time};") + libs
    files = {
        "system/controlDict": ("controlDict", control),
        "system/blockMeshDict": ("blockMeshDict", block_mesh),
        "system/fvSchemes": ("fvSchemes", SCHEMES),
        "system/fvSolution": ("fvSolution", ""),
        "constant/dynamicMeshDict": ("dynamicMeshDict", dynamic_mesh_dict),
    }
    for path, (obj, body) in files.items():
        with open(os.path.join(case, path), "w") as f:
            f.write(foam_file(obj, body))
    with open(os.path.join(case, "0", "pointDisplacement"), "w") as f:
        f.write(foam_file("pointDisplacement", displacement).replace(
            "class dictionary", "class pointVectorField"))
    subprocess.run(["blockMesh", "-case", case], stdout=subprocess.DEVNULL,
                   stderr=subprocess.STDOUT, check=True)
    return case


def run(case):
    result = subprocess.run(["moveDynamicMesh", "-case", case], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    return result.returncode, result.stdout


def refused(code, log, expected):
    """(ok, detail): a FatalIOError with every expected phrase."""
    missing = [e for e in expected if e not in log]
    ok = code != 0 and "FOAM FATAL IO ERROR" in log and not missing
    return ok, f"exit code {code}" + (f", missing {missing}:\n{log[-2500:]}" if not ok else "")


def ran(code, log):
    return code == 0, f"exit code {code}" + ("" if code == 0 else "\n" + log[-2500:])


def run_cases(cases, make):
    """(name, ok, detail) of each (name, text, expected phrases or None:
    must run) case, make(name, text) writing the case."""
    results = []
    for name, text, expected in cases:
        code, log = run(make(name, text))
        results.append((name, *(ran(code, log) if expected is None
                                else refused(code, log, expected))))
    return results


def report(results):
    """Prints each (name, ok, detail) and the count; 1 if any failed."""
    failures = 0
    for name, ok, detail in results:
        print(f"{'PASS' if ok else 'FAIL'} {name}: {detail}", flush=True)
        failures += 0 if ok else 1
    print(f"{len(results) - failures} passed, {failures} failed")
    return 1 if failures else 0


def run_checks(prefix, checks):
    """report() of checks(work), work a new temporary directory (kept with
    KEEP_CASES=1)."""
    work = tempfile.mkdtemp(prefix=prefix)
    try:
        results = checks(work)
    finally:
        if os.environ.get("KEEP_CASES") != "1":
            shutil.rmtree(work, ignore_errors=True)
    return report(results)


def wrong_type(name, entry, value, expected, *more):
    """The case of coupling entry `entry` given `value`: refused, saying
    what it expects (and the further phrases `more`)."""
    return (name, mesh_dict(coupling=f"coupling {{ {entry} {value}; }}"),
            [f"coupling entry '{entry}' expects {expected}", *more])


def main():
    valid_coupling = "addedMass, pressure, residual, addedMassInterval, maxIter, tolerance"
    cases = [
        # name, dynamicMeshDict, expected phrases (None: must run)
        ("valid", mesh_dict(), None),
        ("couplingTypos", mesh_dict(coupling="coupling { maxIters 0; tolerence 7; }"),
         ["unknown coupling entry 'maxIters'", valid_coupling]),
        ("misspeltCoupling", mesh_dict(coupling="couplng { addedMass on; }"),
         ["unknown entry 'couplng'", "accelerationRelaxation", valid_coupling]),
        ("misspeltTopLevel", mesh_dict(coeffs_extra="addedMassInteval 0;"),
         ["unknown entry 'addedMassInteval'", "coupling entry 'addedMassInterval'"]),
        ("misspeltOpenFoamEntry", mesh_dict(coeffs_extra="accelerationRelaxaton 0.5;"),
         ["unknown entry 'accelerationRelaxaton'", "did you mean 'accelerationRelaxation'"]),
        ("wrongCase", mesh_dict(coeffs_extra="Coupling { addedMass off; }"),
         ["unknown entry 'Coupling'", "did you mean 'coupling'"]),
        ("userEntriesForExpansion",
         mesh_dict(coeffs_extra="hingeParameters { stiffness 1e5; } pontoon { mass 50; } line 3;"),
         None),
        ("couplingEntryAtTopLevel", mesh_dict(coeffs_extra="addedMassInterval 5;"),
         ["unknown entry 'addedMassInterval'", "belongs in the coupling sub-dictionary"]),
        ("couplingNotADictionary", mesh_dict(coupling="coupling 5;"),
         ["entry 'coupling' must be a dictionary"]),
        wrong_type("fractionalMaxIter", "maxIter", "2.5", "an integer, got '2.5'"),
        wrong_type("badSwitch", "addedMass", "maybe", "a switch", "maybe"),
        wrong_type("wordTolerance", "tolerance", "small", "a number, got 'small'"),
        wrong_type("listPressure", "pressure", "(p_rgh p)", "the pressure field's name"),
        ("withoutCoeffsDictionary",
         mesh_dict(coeffs_extra="").replace("addedMassRigidBodyMotionCoeffs\n{", "").rstrip()[:-1]
         + "\naddedMassInteval 0;\n",
         ["unknown entry 'addedMassInteval'"]),
    ]
    return run_checks("addedMassEntries.", lambda work: run_cases(
        cases, lambda name, text: make_case(work, name, text))
        + outer_corrector_checks(work))


ONE_CORRECTOR = "PIMPLE nOuterCorrectors 1: the coupling is stable"


def outer_corrector_checks(work):
    """(name, ok, detail): one PIMPLE outer corrector (and only one) is
    warned of as far from converged, naming the docs' table; the run
    goes on."""
    results = []
    for outer, warned in ((1, True), (3, False)):
        case = make_case(work, f"nOuterCorrectors{outer}", mesh_dict())
        with open(os.path.join(case, "system", "fvSolution"), "w") as f:
            f.write(foam_file("fvSolution", f"PIMPLE {{ nOuterCorrectors {outer}; }}"))
        code, log = run(case)
        ok = code == 0 and (ONE_CORRECTOR in log) == warned and (
            not warned or "How many outer correctors" in log)
        results.append((f"nOuterCorrectors {outer}", ok,
                        f"exit code {code}, warned {ONE_CORRECTOR in log}"
                        + ("" if ok else "\n" + log[-2500:])))
    return results


if __name__ == "__main__":
    sys.exit(main())

"""Bad input to the fmuConnector restraint ends in a clear fatal error.

Each variant of a one-body model with one mistake must make rigidBodySim
fail, with a message naming the restraint and what is wrong, and must
leave no time directory behind.
"""
import os
import sys
import tempfile

from foamfmi.bridgecase import Case, fmu_path, fmu_restraint, linear_spring, rigid_body, rigid_body_model, vec
from foamfmi.sixdofcase import SixDoFCase, sixdof_body
from test_sixdof_spring_world import CENTRE, M, J, fmu_spring


def model(fmu, parameters, body_b=None, body="hull", extra=""):
    return rigid_body_model(rigid_body("hull", 2, 0.1, (0, 0, 0), "floating"),
                            fmu_restraint("mooring", fmu, body, parameters, body_b, extra), g=None)


GOOD = f"stiffness 10; damping 0; restLength 1; A.p {vec((0, 0, 0))}; B.p {vec((0, 0, 2))};"


def main():
    spring = fmu_path("linearSpring")
    not_a_zip = tempfile.NamedTemporaryFile(suffix=".fmu", delete=False)
    not_a_zip.write(b"this is not a zip archive\n")
    not_a_zip.close()

    cases = {
        "missing fmu file": (model("/nonexistent/spring.fmu", GOOD), ["mooring", "/nonexistent/spring.fmu"]),
        "space in the fmu path": (
            model("/tmp/my fmus/spring.fmu", GOOD),
            ["restraint mooring: entry 'fmu' \"/tmp/my fmus/spring.fmu\" holds a space",
             "OpenFOAM file name cannot hold"],
        ),
        "not a zip": (model(not_a_zip.name, GOOD), ["mooring", not_a_zip.name]),
        "undeclared parameter": (
            model(spring, GOOD + " stiffnes 3;"),
            ["mooring", "stiffnes", "not declared"],
        ),
        "wrong vector size": (
            model(spring, GOOD.replace("A.p (0.0 0.0 0.0)", "A.p (1 2)")),
            ["mooring", "'A.p' expects a list of 3 numbers", "got '( 1 2 )'"],
        ),
        "scalar for a vector": (
            model(spring, GOOD.replace("A.p (0.0 0.0 0.0)", "A.p 5")),
            ["mooring", "'A.p' expects a list of 3 numbers", "got '5'"],
        ),
        "list for a scalar": (
            model(spring, GOOD.replace("stiffness 10", "stiffness (10 2)")),
            ["mooring", "'stiffness' expects one number"],
        ),
        "vector and element": (
            model(spring, GOOD + " A.p[2] 1;"),
            ["mooring", "entries 'A.p' and 'A.p[2]' both set the FMU parameter A.p[2]"],
        ),
        "misspelt parameters": (
            model(spring, GOOD, extra="paramters { stiffness 3; }"),
            ["mooring", "unknown entry 'paramters'", "bodyB", "parameters"],
        ),
        "misspelt bodyB": (
            model(spring, GOOD, extra="bodyb hull;"),
            ["mooring", "unknown entry 'bodyb'"],
        ),
        "parameters not a dictionary": (
            model(spring, GOOD, extra="parameters 5;").replace(f"parameters {{ {GOOD} }}", ""),
            ["mooring", "entry 'parameters' must be a dictionary"],
        ),
        "unknown restart mode": (
            model(spring, GOOD, extra="restart later;"),
            ["restart", "later", "exact", "fresh"],
        ),
        "unknown body": (model(spring, GOOD, body="barge"), ["restraint mooring", "barge", "hull"]),
        "unknown bodyB": (model(spring, GOOD, "barge"), ["mooring", "barge", "hull"]),
        # A shared line (mooringLine.fmu between two bodies) whose two ends
        # name the same body
        "bodyB the same body": (
            model(fmu_path("mooringLine"), "A.p (0 0 0); B.p (0 0 -1);", "hull"),
            ["restraint mooring", "body and bodyB are the same body hull"],
        ),
        "negative stiffness": (model(spring, GOOD.replace("stiffness 10", "stiffness -10")), ["mooring", "stiffness"]),
        # OpenFOAM merges two entries of one keyword into one, silently;
        # any fmuConnector in the restraints dictionary checks every name
        "restraint named twice": (
            rigid_body_model(rigid_body("hull", 2, 0.1, (0, 0, 0), "floating"),
                             linear_spring("mooring", "hull", (0, 0, 2), (0, 0, 0), 5, 0, 1)
                             + fmu_restraint("mooring", spring, "hull", GOOD), g=None),
            ["restraint mooring is given twice in", "constant/dynamicMeshDict\" (lines "],
        ),
        "built-in restraint named twice beside a connector": (
            rigid_body_model(rigid_body("hull", 2, 0.1, (0, 0, 0), "floating"),
                             linear_spring("tie", "hull", (0, 0, 2), (0, 0, 0), 5, 0, 1)
                             + fmu_restraint("mooring", spring, "hull", GOOD)
                             + linear_spring("tie", "hull", (0, 0, 3), (0, 0, 0), 5, 0, 1), g=None),
            ["restraint tie is given twice in", "constant/dynamicMeshDict\" (lines "],
        ),
    }

    failures = 0
    for name, (text, expected) in cases.items():
        case = Case("errors", text, 0.1, 0.01)
        print(f"-- {name}", flush=True)
        log = case.run(expect_failure=True)
        missing = [e for e in expected if e not in log]
        written = [d for d in os.listdir(case.dir) if d not in ("system", "constant", "postProcessing")]
        if missing or written:
            failures += 1
            print(f"FAIL {name}: message lacks {missing}, left {written}\n{log[-1500:]}")
        else:
            message = [line for line in log.splitlines() if any(e in line for e in expected)]
            print(f"PASS {name}: {message[0].strip()[:150] if message else ''}")
        case.cleanup()
    os.unlink(not_a_zip.name)

    # The same in a sixDoF body's restraints
    builtin = """            spring_fmu
            {
                sixDoFRigidBodyMotionRestraint linearSpring;
                anchor (0 0 2); refAttachmentPt (0 0 0.5); stiffness 5; damping 0; restLength 1;
            }
"""
    case = SixDoFCase("errors.sixdof", {"fmu": sixdof_body(M, J, CENTRE, "Newmark", builtin + fmu_spring("fmu"))},
                      0.1, 0.01)
    log = case.run(expect_failure=True)
    expected = "restraint spring_fmu is given twice in"
    ok = expected in log and "constant/sixDoFBodies\" (lines " in log
    failures += 0 if ok else 1
    print(f"{'PASS' if ok else 'FAIL'} sixDoF restraint named twice" + ("" if ok else f"\n{log[-1500:]}"))
    case.cleanup()
    print(f"{len(cases) + 1 - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

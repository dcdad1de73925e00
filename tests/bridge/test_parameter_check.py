"""A parameter the FMU refuses stops the run when the restraint dictionary is
read, with a FatalIOError at the dictionary entry that sets it.

The FMU checks its parameters when it leaves initialisation mode, which the
connector's instance does at the first evaluation, with the bodies'
kinematics. The restraint lets a second instance leave it when the
dictionary is read; a refusal that the FMU names in its log category
refusedParameter ("<name> <code>: <message>") is the dictionary's error:

- negative-stiffness: linearSpring's stiffness -10, a scalar entry;
- zero-axis: hinge's A.axis (0 0 0), a vector entry (the FMU names A.axis);
- parallel-reference: hinge's B.ref along B.axis, refused with the value of
  another entry (code inconsistent; the message names B.axis too);
- seabed-without-diameter: mooringLine's diameter 0 with seabedContact 1
  (inconsistent), the entry that sets diameter;

all stop before the model is built ("Model with ... bodies" is never
printed), with FOAM FATAL IO ERROR, the entry's path in the dictionary
(...parameters.stiffness; ...parameters/stiffness from OpenFOAM v2312 on)
and the FMU's reason.

- start-below-seabed: a refusal that depends on the inputs is not the
  dictionary's: mooringLine with seabedContact 1 refuses the inputs' start
  values (the fairlead below the anchor), but the case's body holds the
  fairlead above it, so the run goes on as before.

And what the restraint uses is in the log when it starts (reported): the
FMU's file, FMI version, model and SHA-256, and every parameter's value,
those the case does not give marked as the FMU's defaults (linearSpring
without damping: 0).
"""
import hashlib
import os
import sys

from foamfmi.bridgecase import Case, fmu_path, rigid_body, vec


def model(fmu, parameters, z=0.0):
    return f"""
    solver {{ type symplectic; }}
    bodies
    {{
{rigid_body("hull", 2, 0.1, (0, 0, z), "floating")}
    }}
    restraints
    {{
        mooring
        {{
            type fmuConnector;
            body hull;
            fmu "{fmu}";
            parameters
            {{
                {parameters}
            }}
        }}
    }}
"""


LINE = ("unstretchedLength 1.6; EA 5000; axialDamping 10; massPerLength 0.117; diameter 0.0044; "
        "waterDensity 998.2; gravity 9.81; seabedContact 1; segments 10; "
        f"A.p {vec((0.1, 0.1, -0.03))}; B.p {vec((0.95, 0.95, 0))};")

# name: (fmu, parameters, body height, words of the fatal error; None: the run succeeds)
CASES = {
    "negative-stiffness": (
        "linearSpring",
        f"stiffness -10; restLength 1; A.p {vec((0, 0, 0))}; B.p {vec((0, 0, 2))};",
        0.0,
        ["FOAM FATAL IO ERROR", "restraint mooring: the FMU refuses parameter 'stiffness'",
         "parameter stiffness = -10", "restraints.mooring.parameters.stiffness"],
    ),
    "zero-axis": (
        "hinge",
        f"A.axis {vec((0, 0, 0))};",
        0.0,
        ["FOAM FATAL IO ERROR", "restraint mooring: the FMU refuses parameter 'A.axis'",
         "parameter A.axis", "restraints.mooring.parameters.A.axis"],
    ),
    "parallel-reference": (
        "hinge",
        f"B.axis {vec((1, 0, 0))}; B.ref {vec((-2, 0, 0))};",
        0.0,
        ["FOAM FATAL IO ERROR", "restraint mooring: the FMU refuses parameter 'B.ref'",
         "parameter B.ref = (-2, 0, 0) is parallel to B.axis", "restraints.mooring.parameters.B.ref"],
    ),
    "seabed-without-diameter": (
        "mooringLine",
        LINE.replace("diameter 0.0044;", "diameter 0;"),
        0.5,
        ["FOAM FATAL IO ERROR", "restraint mooring: the FMU refuses parameter 'diameter'",
         "parameter diameter = 0 m is out of range", "restraints.mooring.parameters.diameter"],
    ),
    "start-below-seabed": ("mooringLine", LINE, 0.5, None),
}


def reported():
    """1 if the restraint's report of its FMU and parameters is wrong."""
    fmu = fmu_path("linearSpring")
    with open(fmu, "rb") as f:
        sha256 = hashlib.sha256(f.read()).hexdigest()
    case = Case("parameterReport", model(fmu, f"stiffness 10; restLength 1; A.p {vec((0, 0, 0.1))}; "
                                              f"B.p {vec((0, 0, 2))};"), 0.02, 0.01)
    log = case.run()
    expected = [f"Restraint mooring: FMU \"{fmu}\" (FMI 2.0, linearSpring, SHA-256 {sha256})\n",
                "\n    stiffness 10\n", "\n    restLength 1\n",
                "\n    damping 0  (not given: the FMU's default)\n",
                "\n    A.p (0 0 0.1)\n", "\n    B.p (0 0 2)\n"]
    missing = [e.strip() for e in expected if e not in log]
    case.cleanup()
    if missing:
        start = log.find("Restraint mooring: FMU")
        print(f"FAIL reported: the log lacks {missing}\n{log[start:start + 800]}")
        return 1
    print("PASS reported: the FMU with its SHA-256, the given parameters, damping 0 as the FMU's default")
    return 0


def main():
    failures = reported()
    for name, (fmu, parameters, z, words) in CASES.items():
        print(f"-- {name}", flush=True)
        case = Case("parameterCheck", model(fmu_path(fmu), parameters, z), 0.02, 0.01)
        log = case.run(expect_failure=words is not None)
        problems = []
        if words is not None:
            # The entry's path in the IO error: OpenFOAM v1912 joins its
            # keywords with '.', v2312 with '/'
            problems += [f"lacks '{w}'" for w in words
                         if w not in log and not (w.startswith("restraints.")
                                                  and w.replace(".mooring.parameters.",
                                                                "/mooring/parameters/")
                                                  .replace("restraints.", "restraints/", 1)
                                                  in log)]
            if "Model with" in log:
                problems.append("the model was built: the error came after the dictionary was read")
            written = [d for d in os.listdir(case.dir) if d not in ("system", "constant", "postProcessing")]
            if written:
                problems.append(f"left {written}")
        elif not os.path.isdir(os.path.join(case.dir, "0.02")):
            problems.append("no time 0.02 written")
        if problems:
            failures += 1
            print(f"FAIL {name}: {problems}\n{log[-2000:]}")
        else:
            error = [line.strip() for line in log.splitlines() if "refuses" in line]
            print(f"PASS {name}" + (f": {error[0][:200]}" if error else ": runs"))
        case.cleanup()
    print(f"{len(CASES) + 1 - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

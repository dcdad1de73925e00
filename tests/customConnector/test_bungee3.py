"""The example's FMI 3.0 twin, bungee3.fmu, is the bungee of bungee.fmu.

Both are built from a copy of examples/customConnector (bungee.c,
modelDescription.xml; bungee3.c, fmi3/modelDescription.xml,
fmi3/terminalsAndIcons.xml; the Makefile) with the example's own Makefile,
the standards' headers and nothing else of the project. Then:

- bungee3.fmu builds -Wall -Wextra -pedantic clean, passes the project's
  schema check of its 3.0 FMUs (tests/fmu/validateSchema.cmake) and
  fmusim check, whose report is the 2.0 bungee's word for word;
- fmusim run (the kinematics of one input table moving about their start
  values, rotations included, the line going slack and taut) and fmusim
  twobody (explicit and implicit) give the 2.0 bungee's text number for
  number: bit for bit, since both FMUs run the same law in the same order
  of operations, built by the same compiler with the same flags, and fmusim
  prints 17 significant digits;
- the parameter refusals are the 2.0 bungee's, fmi3 for fmi2;
- the example's case (examples/customConnector/case: the fender on the
  bungee, rigidBodySim, no CFD) run with fmu "<constant>/fmu/bungee3.fmu"
  writes the 2.0 FMU's bodies.dat byte for byte and its bungee.dat but for
  the header line naming the FMU; restarted from its t = 4 the two again
  write the same bytes.

    python3 test_bungee3.py FMUSIM
"""
import os
import re
import shutil
import subprocess
import sys

import customfmu

sys.path.insert(0, os.path.join(customfmu.TOP, "tests", "fmi3"))
import sameAnswers  # noqa: E402

CASE = os.path.join(customfmu.EXAMPLE, "case")
# The line between a point above A's reference point and one beside and
# below B's, about its rest length for the inputs' start values, so that
# the table's motions make it go slack and taut
LINE = ["stiffness=400", "cubicStiffness=2000", "restLength=0.715",
        "A.p[3]=0.15", "B.p[1]=0.3", "B.p[3]=-0.5"]
REFUSED = (["stiffness=-5"], ["cubicStiffness=-1"], ["restLength=-1"],
           ["stiffness=0", "cubicStiffness=0"])


def fmusim(folder, *args):
    """(exit code, stdout, stderr) of fmusim in folder."""
    done = subprocess.run([sameAnswers.FMUSIM, *args], cwd=folder, capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr


def with_sets(sets):
    return [a for s in sets for a in ("--set", s)]


def same_outputs(folder, check):
    fmu2, fmu3 = (os.path.join(folder, f) for f in ("bungee.fmu", "bungee3.fmu"))
    table = os.path.join(folder, "inputs.csv")
    sameAnswers.input_table(sameAnswers.inputs_of(fmu2), table)
    run = ["run", "--stop-time", "0.1", "--step-size", "0.005", "--input-file", table, *with_sets(LINE)]
    out2, out3 = sameAnswers.fmusim(*run, fmu2), sameAnswers.fmusim(*run, fmu3)
    rows, cols = sameAnswers.same(out3, out2, "fmusim run")
    lines = out2.splitlines()
    column = lines[0].split(",").index("tension")
    tensions = [float(r.split(",")[column]) for r in lines[1:]]
    slack, taut = sum(t == 0 for t in tensions), sum(t > 0 for t in tensions)
    check(slack and taut, "fmusim run: the same outputs as bungee.fmu",
          f"{rows} rows of {cols} outputs, text equal ({slack} rows slack, {taut} taut)")
    for scheme in ("explicit", "implicit"):
        args = ["twobody", "--stop-time", "2", "--scheme", scheme, *with_sets(LINE[:2]),
                "--set", "restLength=1", "--set", "A.p[3]=0.15", "--set", "B.p[1]=0.1",
                "--A.velocity", "1.5 0 -1", "--A.angular-velocity", "0 0.3 0.1",
                "--B.position", "1.5 0.1 0.2", "--B.velocity", "-0.05 0.02 0"]
        rows, cols = sameAnswers.same(sameAnswers.fmusim(*args, fmu3), sameAnswers.fmusim(*args, fmu2),
                                      f"fmusim twobody {scheme}")
        check(True, f"fmusim twobody {scheme}: the same as bungee.fmu", f"{rows} rows of {cols} columns, text equal")


def same_refusals(folder, check):
    for sets in REFUSED:
        args = ["run", "--stop-time", "0.01", *with_sets(sets)]
        code2, _, err2 = fmusim(folder, *args, "bungee.fmu")
        code3, _, err3 = fmusim(folder, *args, "bungee3.fmu")
        expected = re.sub(r"bungee(?!3)", "bungee3", err2.replace("fmi2", "fmi3"))
        check(code2 == code3 == 5 and err3 == expected and sets[0].split("=")[0] in err3,
              f"refused: {' '.join(sets)}",
              f"exit {code3}, {err3.strip().splitlines()[-1] if err3.strip() else '(no message)'}"
              + ("" if err3 == expected else f"; 2.0 gave, fmi3 for fmi2: {expected!r}"))


def case_copy(name, fmu):
    """The example's case (constant, system) in a temporary folder, its
    restraint naming <constant>/fmu/<fmu>."""
    folder = customfmu.tempfile.mkdtemp(prefix=f"customConnector.{name}.")
    for sub in ("constant", "system"):
        shutil.copytree(os.path.join(CASE, sub), os.path.join(folder, sub),
                        ignore=shutil.ignore_patterns("fmu"))
    os.makedirs(os.path.join(folder, "constant", "fmu"))
    dictionary = os.path.join(folder, "constant", "dynamicMeshDict")
    with open(dictionary) as f:
        text = f.read()
    entry = 'fmu         "<constant>/fmu/bungee.fmu";'
    if text.count(entry) != 1:
        raise AssertionError(f"the example's dynamicMeshDict has no single {entry}")
    with open(dictionary, "w") as f:
        f.write(text.replace(entry, f'fmu         "<constant>/fmu/{os.path.basename(fmu)}";'))
    shutil.copy(fmu, os.path.join(folder, "constant", "fmu"))
    return folder


def rigid_body_sim(case):
    done = subprocess.run(["rigidBodySim", "-case", case], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    if done.returncode != 0:
        raise AssertionError(f"rigidBodySim failed on {case}:\n{done.stdout[-3000:]}")


def results(case, start):
    """bodies.dat and bungee.dat without its header line naming the FMU."""
    with open(os.path.join(case, "postProcessing", "rigidBodySim", start, "bodies.dat")) as f:
        bodies = f.read()
    with open(os.path.join(case, "postProcessing", "fmuConnectors", start, "bungee.dat")) as f:
        first, line = f.read().split("\n", 1)
    if not first.startswith("# Connector bungee: FMU"):
        raise AssertionError(f"bungee.dat of {case} begins {first!r}")
    return bodies, line


def restart(case, time):
    """The case again from its written time, to the same end."""
    for entry in os.listdir(case):
        if entry == "postProcessing" or re.fullmatch(r"[0-9.]+", entry) and float(entry) > float(time):
            shutil.rmtree(os.path.join(case, entry))
    control = os.path.join(case, "system", "controlDict")
    with open(control) as f:
        text = f.read()
    with open(control, "w") as f:
        f.write(re.sub(r"\nstartTime\s+0;", f"\nstartTime       {time};", text))
    rigid_body_sim(case)


def same_motion(folder, check):
    cases = {v: case_copy(f"case{v}", os.path.join(folder, fmu))
             for v, fmu in (("2.0", "bungee.fmu"), ("3.0", "bungee3.fmu"))}
    for case in cases.values():
        rigid_body_sim(case)
    (bodies2, line2), (bodies3, line3) = (results(cases[v], "0") for v in ("2.0", "3.0"))
    rows = len(bodies2.splitlines())
    header = [line for line in bodies3.splitlines() if line.startswith("#")][-1][1:].split()
    z = header.index("fender.c.z")
    lowest = min(float(r.split()[z]) for r in bodies3.splitlines() if not r.startswith("#"))
    check(bodies2 == bodies3 and line2 == line3 and rows > 8000,
          "the example's case with bungee3.fmu: the motion of bungee.fmu",
          f"bodies.dat ({rows} lines) and bungee.dat byte for byte "
          f"{'equal' if bodies2 == bodies3 and line2 == line3 else 'DIFFERENT'}; lowest z {lowest:.4f} m")
    for case in cases.values():
        restart(case, "4")
    (bodies2, line2), (bodies3, line3) = (results(cases[v], "4") for v in ("2.0", "3.0"))
    check(bodies2 == bodies3 and line2 == line3 and len(bodies3.splitlines()) > 4000,
          "restarted from t = 4 (the FMU's serialized state)",
          f"{len(bodies3.splitlines())} lines, the 2.0 FMU's bytes: {bodies2 == bodies3 and line2 == line3}")
    for case in cases.values():
        if os.environ.get("KEEP_CASES") != "1":
            shutil.rmtree(case, ignore_errors=True)


def exports_every_function(fmu, check):
    """The binary exports every function of the FMI 3.0 headers (the names
    fmi3Functions.h defines), as importers that load them all before they
    instantiate need (the Reference FMUs' fmusim refused the example for
    fmi3EnterContinuousTimeMode)."""
    headers = os.environ.get("FMI3_HEADERS_DIR",
                             os.path.join(customfmu.TOP, "..", "shared", "fmi3", "headers"))
    with open(os.path.join(headers, "fmi3Functions.h")) as f:
        functions = set(re.findall(r"^#define (fmi3\w+) +fmi3FullName\(", f.read(), re.M))
    folder = os.path.dirname(fmu)
    subprocess.run(["unzip", "-o", "-q", fmu, "binaries/*", "-d", os.path.join(folder, "unzipped")],
                   check=True)
    library = os.path.join(folder, "unzipped", "binaries", "x86_64-linux", "bungee3.so")
    listing = subprocess.run(["nm", "-D", "--defined-only", library], capture_output=True,
                             text=True, check=True).stdout
    exported = {line.split()[-1] for line in listing.splitlines() if line.strip()}
    missing = sorted(functions - exported)
    check(len(functions) > 50 and not missing,
          "exports every function of the FMI 3.0 headers",
          f"{len(functions)} functions in fmi3Functions.h" + (f"; missing {missing}" if missing else ""))


def main(fmusim_path):
    sameAnswers.FMUSIM = fmusim_path
    check = customfmu.Checks()
    folder = customfmu.copy_example("fmi3", tuple(dict.fromkeys(customfmu.SOURCES + customfmu.SOURCES3)))
    fmu3, make_output = customfmu.build(folder, "bungee3.fmu")
    customfmu.build(folder, "bungee.fmu")
    check("warning" not in make_output, "builds on its own, -Wall -Wextra -pedantic clean",
          f"make bungee3.fmu in a copy of the example; {fmu3}")
    problems = customfmu.fmi3_schema_errors(fmu3)
    check(not problems, "modelDescription.xml and terminalsAndIcons.xml against the FMI 3.0 XSD",
          problems or "valid (tests/fmu/validateSchema.cmake)")

    exports_every_function(fmu3, check)

    code, report, _ = fmusim(folder, "check", "bungee3.fmu")
    code2, report2, _ = fmusim(folder, "check", "bungee.fmu")
    failed = [line for line in report.splitlines() if line.startswith("FAIL")]
    check(code == 0 and not failed and report == report2, "fmusim check: bungee.fmu's report",
          f"exit {code}, {report.strip().splitlines()[-1]}; {failed or 'no FAIL'}"
          + ("" if report == report2 else f"\n2.0:\n{report2}\n3.0:\n{report}"))

    same_outputs(folder, check)
    same_refusals(folder, check)
    same_motion(folder, check)

    if os.environ.get("KEEP_CASES") != "1":
        shutil.rmtree(folder, ignore_errors=True)
    print(f"{check.passed} passed, {check.failed} failed")
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

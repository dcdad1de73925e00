"""The bridge (fmuConnector for rigidBodyMotion through rigidBodySim, and
for sixDoFRigidBodyMotion through sixDoFSim: no CFD) takes an FMI 3.0
connector FMU through the same importer, wherever it takes a 2.0 one. The
cases of tests/bridge (two bodies joined by the spring, also with the
spring in a process of its own; the hinged chain; a body moored by
catenary.fmu and one by mooringLine.fmu; two sixDoF bodies joined by the
spring) run with the 3.0 FMUs of build/fmus/fmi3 give the bodies' motion,
every connector output and the mooring lines' VTK files of the 2.0 FMUs,
byte for byte, under the same names (shape.x/y/z[i] in both); a
run restarted from a written time continues the 3.0 FMUs' states; a 3.0
FMU whose A.r has four elements is refused naming the variable and what
was expected.
"""
import os
import re
import shutil
import sys
import zipfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "bridge"))
from foamfmi import bridgecase  # noqa: E402
from foamfmi import sixdofcase  # noqa: E402
import test_catenary_world  # noqa: E402
import test_hinge  # noqa: E402
import test_sixdof_two_bodies  # noqa: E402
import test_two_bodies  # noqa: E402

FMU_DIR = os.environ["FOAMFMI_FMU_DIR"]


def with_fmus(directory, make_model):
    """The model's text with fmu "<directory>/<name>.fmu" entries."""
    saved = os.environ["FOAMFMI_FMU_DIR"]
    os.environ["FOAMFMI_FMU_DIR"] = directory
    try:
        return make_model()
    finally:
        os.environ["FOAMFMI_FMU_DIR"] = saved


def files(case):
    """Every file the run wrote under postProcessing/ and VTK/, by path."""
    found = {}
    for sub in ("postProcessing", "VTK"):
        for root, _, names in os.walk(os.path.join(case.dir, sub)):
            for name in names:
                path = os.path.join(root, name)
                with open(path) as f:
                    found[os.path.relpath(path, case.dir)] = f.read()
    return found


def columns(text):
    """{column name: values} of a table whose last '#' line names them."""
    names, rows = None, []
    for line in text.splitlines():
        if line.startswith("#"):
            names = line[1:].split()
        elif line.strip():
            rows.append(line.split())
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}


def compare(name, make_model, end, dt, write, kind=bridgecase.Case):
    cases = {}
    for version, directory in (("2.0", FMU_DIR), ("3.0", os.path.join(FMU_DIR, "fmi3"))):
        case = kind(f"fmi3bridge.{name}.{version}",
                    with_fmus(directory, make_model), end, dt, write)
        case.run(n_iter=2)
        cases[version] = case
    out2, out3 = files(cases["2.0"]), files(cases["3.0"])
    problems = []
    if sorted(out2) != sorted(out3):
        problems.append(f"other files: {sorted(out2)} and {sorted(out3)}")
    for path in sorted(set(out2) & set(out3)):
        a, b = out2[path], out3[path]
        if path.endswith(".dat") and a != b:
            # the header names the FMU's file, which differs: the same
            # columns, by name
            ca, cb = columns(a), columns(b)
            if ca != cb:
                problems.append(f"{path} differs")
        elif not path.endswith(".dat") and a != b:
            problems.append(f"{path} differs")
    print(f"{'PASS' if not problems else 'FAIL'} {name}: {len(out2)} files"
          + "".join("\n    " + p for p in problems))
    return cases, not problems


def refused_dimensions():
    """A 3.0 spring whose A.r has 4 elements: a FatalError naming it."""
    source = os.path.join(FMU_DIR, "fmi3", "linearSpring.fmu")
    work = bridgecase.Case("fmi3bridge.dims", "", 0.1, 0.01).dir
    target = os.path.join(work, "linearSpring4.fmu")
    with zipfile.ZipFile(source) as zin, zipfile.ZipFile(target, "w") as zout:
        for item in zin.infolist():
            data = zin.read(item.filename)
            if item.filename == "modelDescription.xml":
                text = data.decode()
                text = re.sub(r'(name="A\.r"[^>]*start=")0 0 0(">\s*<Dimension start=")3',
                              r"\g<1>0 0 0 0\g<2>4", text, count=1)
                data = text.encode()
            zout.writestr(item, data)
    model = with_fmus(os.path.join(FMU_DIR, "fmi3"),
                      lambda: test_two_bodies.model("Newmark")).replace(
        os.path.join(FMU_DIR, "fmi3", "linearSpring.fmu"), target)
    case = bridgecase.Case("fmi3bridge.dims", model, 0.1, 0.01)
    log = case.run(expect_failure=True)
    expected = "A.r is an array of dimensions [4], expected an array of dimensions [3]"
    ok = expected in log
    print(f"{'PASS' if ok else 'FAIL'} wrong dimensions refused: "
          + (expected if ok else log[-2000:]))
    shutil.rmtree(work, ignore_errors=True)
    case.cleanup()
    return ok


def restarted(case):
    """The 3.0 case run again from its middle write time: the same end."""
    ends = files(case)
    case.set_time(0.25, 0.5, 0.01, 0.25)
    with open(os.path.join(case.dir, "system", "controlDict")) as f:
        text = f.read().replace("startFrom startTime;", "startFrom latestTime;")
    shutil.rmtree(os.path.join(case.dir, "0.5"))
    with open(os.path.join(case.dir, "system", "controlDict"), "w") as f:
        f.write(text.replace("startTime 0.25;", "startTime 0;"))
    case.run(n_iter=2)
    again = columns(files(case)[os.path.join("postProcessing", "rigidBodySim", "0.25", "bodies.dat")])
    first = columns(ends[os.path.join("postProcessing", "rigidBodySim", "0", "bodies.dat")])
    ok = all(again[n][-1] == first[n][-1] for n in first)
    print(f"{'PASS' if ok else 'FAIL'} restart of the 3.0 spring from t = 0.25: "
          "the end state of the uninterrupted run")
    return ok


def main():
    ok = True
    cases, same = compare("twoBodies", lambda: test_two_bodies.model("Newmark"), 0.5, 0.01, 0.25)
    ok &= same and restarted(cases["3.0"])
    for c in cases.values():
        c.cleanup()
    for name, make, end, dt in (
        ("hinge", lambda: test_hinge.model(1e4), 0.2, test_hinge.DT),
        ("catenaryWorld", lambda: test_catenary_world.model(3e4, 60.0, 1e4), 0.4, 0.02),
        ("twoBodiesIsolationProcess",
         lambda: test_two_bodies.model("Newmark").replace(
             "type fmuConnector;", "type fmuConnector;\n            isolation process;"),
         0.2, 0.01),
    ):
        cases, same = compare(name, make, end, dt, end / 2)
        ok &= same
        for c in cases.values():
            c.cleanup()
    for name, make, end, dt in (
        ("sixDoFTwoBodies", test_sixdof_two_bodies.bodies, 0.2, 0.005),
    ):
        cases, same = compare(name, make, end, dt, end / 2, sixdofcase.SixDoFCase)
        ok &= same
        for c in cases.values():
            c.cleanup()
    ok &= refused_dimensions()
    if not ok:
        sys.exit(1)


if __name__ == "__main__":
    main()

"""No row lost without a word: rigidBodySim and sixDoFSim run under a
file-size limit (ulimit -f, SIGXFSZ ignored, so that the write fails with
EFBIG as on a full disk instead of killing the process).

Five cases: rigidBodySim with a spring to the world (linearSpring.fmu),
with a catenary line (catenary.fmu) and with OpenFOAM's own spring;
sixDoFSim with the spring FMU and with OpenFOAM's own. A connector's rows
are the longer, so its file reaches the limit first; without one,
bodies.dat does. Each run must
 - stop with a non-zero exit code and a FatalError that names the file
   that reached the limit, the row's time and the cause;
 - leave every file it wrote (bodies.dat, the connector's .dat) with whole
   rows only: each ends in a newline and every row has the header's
   number of columns;
 - leave the file it names within one row of the limit (the limit was
   hit there, not elsewhere).
Without the checks, the run ended with exit code 0 and a cut row.

Then a full disk for the files written at a write time, one at a time:
the file's temporary name (each is written to <file>.tmp and renamed) is
a link to /dev/full, whose writes fail with ENOSPC. rigidBodySim with
catenary.fmu writes 0.25 and 0.5; at 0.25 the connector's state
(uniform/fmuConnectors/<name>), the line's VTK file (line_25.vtk: time
index 25) or the VTK series is on the full disk. Each run must stop with a
FatalError that names what was written, the file, t = 0.25 and "No space
left on device" (before: the VTK series was renamed unchecked, and the
state's message named neither the time nor the cause), and leave the
connector's and the bodies' rows whole, up to 0.25 at least.
"""
import os
import resource
import signal
import subprocess
import sys

from foamfmi.postprocessing import PostProcessingError, whole_rows
from foamfmi.bridgecase import (Case, check, fmu_path, fmu_restraint, linear_spring, rigid_body,
                                rigid_body_model, summary)
from foamfmi.mooringcase import DEPTH, catenary_parameters
from foamfmi.sixdofcase import SixDoFCase, sixdof_body, vec

LIMIT = 2000000  # bytes: above an FMU's library (1.6 MB), which is unpacked too
SPRING = {"stiffness": 50.0, "damping": 0.5, "restLength": 0.5}


def limited():
    """In the child: the file-size limit, and SIGXFSZ ignored."""
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (LIMIT, LIMIT))


def run_limited(command):
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, preexec_fn=limited)
    return result.returncode, result.stdout


def verdict(name, returncode, log, files, expected=None):
    """Checks of one run (1 for each that failed); files: {label: path};
    expected: the label of the file that must reach the limit first (None:
    any of them)."""
    checks = [check(f"{name}: stops with an error", returncode != 0, f"exit code {returncode}")]
    message = [line for line in log.splitlines() if "cannot write" in line]
    named = [label for label, path in files.items() if any(path in line for line in message)]
    checks.append(check(
        f"{name}: the FatalError names the file, the row's time and the cause",
        len(named) == 1 and (expected is None or named == [expected])
        and any("the row of t = " in line and "File too large" in line for line in message),
        " / ".join(message[:2]) or log[-600:]))
    for label, path in files.items():
        try:
            rows, longest = whole_rows(path)
            ok, detail = True, f"{rows} whole rows, {os.path.getsize(path)} bytes"
            if label in named:
                ok = LIMIT - longest < os.path.getsize(path) <= LIMIT
                detail += f", within one row ({longest} bytes) of the limit {LIMIT}"
        except PostProcessingError as error:
            ok, detail = False, str(error)
        checks.append(check(f"{name}: {label} has whole rows only", ok, detail))
    return checks


def full_disk_checks(cases):
    """The files of a write time on a full disk (see the module's text)."""
    checks = []
    line = fmu_restraint("line", fmu_path("catenary"), "hull",
                         {**catenary_parameters(seabedFriction=0), "A.p": "(0 0 0)",
                          "B.p": (-80.0, 0.0, -DEPTH)}, report="off")
    for label, relative, what in [
            ("connector state", ("0.25", "uniform", "fmuConnectors", "line"), "the state line"),
            ("VTK file", ("VTK", "fmuConnectors", "line_25.vtk"), "the line shape of connector line"),
            ("VTK series", ("VTK", "fmuConnectors", "line.vtk.series"),
             "the VTK series of connector line")]:
        name = f"rigidBodySim, {label} on a full disk"
        case = Case(name.replace(" ", ".").replace(",", ""),
                    rigid_body_model(rigid_body("hull", 1e6, 1e5, (0, 0, 0), "Px"), line,
                                     g=(0, 0, -9.81)), 0.5, 0.01, write_interval=0.25)
        cases.append(case)
        path = os.path.join(case.dir, *relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        os.symlink("/dev/full", path + ".tmp")
        result = subprocess.run(["rigidBodySim", "-case", case.dir], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True)
        message = [l for l in result.stdout.splitlines() if "cannot write" in l]
        expected = [what, path, "t = 0.25", "No space left on device"]
        checks.append(check(
            f"{name}: stops, the FatalError names what, the file, the time and the cause",
            result.returncode != 0 and len(message) == 1 and all(e in message[0] for e in expected),
            f"exit code {result.returncode}: " + (" / ".join(message) or result.stdout[-600:])))
        for table, table_path in [
                ("bodies", ("postProcessing", "rigidBodySim", "0", "bodies.dat")),
                ("connector", ("postProcessing", "fmuConnectors", "0", "line.dat"))]:
            try:
                rows, _ = whole_rows(os.path.join(case.dir, *table_path))
                # 25 steps to 0.25 (bodies.dat: and the start row)
                ok, detail = rows >= 25, f"{rows} whole rows"
            except (PostProcessingError, OSError) as error:
                ok, detail = False, str(error)
            checks.append(check(f"{name}: {table} rows whole, to 0.25 at least", ok, detail))
    return checks


def rigid_case(name, restraint, body):
    return Case(name, rigid_body_model(body, restraint, g=(0, 0, -9.81)), 100.0, 0.001)


def main():
    checks = []
    cases = []
    spring = fmu_restraint("spring", fmu_path("linearSpring"), "hull",
                           {**SPRING, "A.p": "(0 0 0)", "B.p": "(0 0 1.2)"}, report="off")
    line = fmu_restraint("line", fmu_path("catenary"), "hull",
                         {**catenary_parameters(seabedFriction=0), "A.p": "(0 0 0)",
                          "B.p": (-80.0, 0.0, -DEPTH)}, report="off")
    # The spring's body hangs from it and bobs; the line's body, heavy, slides
    # on x 80 m from the anchor, the line partly on the seabed. A
    # connector's rows are the longer (180 bytes against bodies.dat's 90):
    # its file reaches the limit first; with OpenFOAM's own spring instead,
    # bodies.dat does.
    builtin = linear_spring("spring", "hull", (0, 0, 1.2), (0, 0, 0), 50.0, 0.5, 0.5)
    for name, restraint, connector, body, expected in [
            ("rigidBodySim spring", spring, "spring",
             rigid_body("hull", 2.0, 0.1, (0, 0, 0.6), "Pz"), "connector"),
            ("rigidBodySim catenary", line, "line",
             rigid_body("hull", 1e6, 1e5, (0, 0, 0), "Px"), "connector"),
            ("rigidBodySim built-in spring", builtin, None,
             rigid_body("hull", 2.0, 0.1, (0, 0, 0.6), "Pz"), "bodies")]:
        case = rigid_case(name.replace(" ", "."), restraint, body)
        cases.append(case)
        returncode, log = run_limited(["rigidBodySim", "-case", case.dir])
        files = {"bodies": os.path.join(case.dir, "postProcessing", "rigidBodySim", "0", "bodies.dat")}
        if connector:
            files["connector"] = os.path.join(case.dir, "postProcessing", "fmuConnectors", "0",
                                              connector + ".dat")
        checks += verdict(name, returncode, log, files, expected)

    sixdof_spring = f"""            spring
            {{
                sixDoFRigidBodyMotionRestraint fmuConnector;
                fmu "{fmu_path('linearSpring')}";
                body hull;
                report off;
                parameters
                {{
                    stiffness 50; damping 0.5; restLength 0.5;
                    A.p (0 0 0); B.p {vec((0.0, 0.0, 1.2))};
                }}
            }}
"""
    sixdof_builtin = """            spring
            {
                sixDoFRigidBodyMotionRestraint linearSpring;
                anchor (0 0 1.2); refAttachmentPt (0 0 0.6);
                stiffness 50; damping 0.5; restLength 0.5;
            }
"""
    for name, restraints, expected in [("sixDoFSim spring", sixdof_spring, "connector"),
                                       ("sixDoFSim built-in spring", sixdof_builtin, "bodies")]:
        case = SixDoFCase(name.replace(" ", "."),
                          {"hull": sixdof_body(2.0, 0.1, (0.0, 0.0, 0.6), "Newmark", restraints)},
                          100.0, 0.001, g=(0, 0, -9.81))
        cases.append(case)
        returncode, log = run_limited(["sixDoFSim", "-case", case.dir])
        files = {"bodies": os.path.join(case.dir, "postProcessing", "sixDoFSim", "0", "bodies.dat")}
        if expected == "connector":
            files["connector"] = os.path.join(case.dir, "postProcessing", "fmuConnectors", "0",
                                              "spring.dat")
        checks += verdict(name, returncode, log, files, expected)

    checks += full_disk_checks(cases)

    failures = sum(checks)
    if not failures:
        for case in cases:
            case.cleanup()
    return summary(len(checks), failures)


if __name__ == "__main__":
    sys.exit(main())

"""A run ended by a signal keeps the connector's completed rows, which a
writer thread writes (fmuConnectorRows, docs/restraint.md): the solver
only copies a step's numbers, the writer formats and writes the rows of
every 2 ms.

rigidBodySim with the spring FMU on a bobbing body runs steps of 1 ms of
simulated time as fast as it can (tens of thousands a second), no time
written before the end, and is stopped at a moment the test does not
choose:
 - SIGTERM and SIGINT: the importer's signal handler waits for the writer
   (fmuImport's ending hook), so the connector's file holds every step the
   bodies' file holds, but for the step under way (its row is pending
   until the next step begins): at most one row fewer;
 - SIGKILL: no handler runs; the rows of the last 2 ms may be lost (a
   loaded machine may keep the writer waiting for a core: the bound is
   what the run makes in 300 ms, which a writer that never wrote before
   the end, or wrote only at exit, would exceed);
and every file holds whole rows only (each row ends in a newline and has
the header's number of columns), but that a SIGKILL landing inside a
write may cut the last row: the kernel copies a write into the file a
page (4 KiB) at a time and stops between pages for a fatal signal, so
a batch of rows that crosses a page boundary can be cut there. The rows
before it are whole; the cut row counts as lost.
"""
import os
import signal
import subprocess
import sys
import time

from foamfmi.bridgecase import Case, check, fmu_path, fmu_restraint, rigid_body, rigid_body_model, summary
from foamfmi.postprocessing import PostProcessingError, whole_rows

SPRING = {"stiffness": 50.0, "damping": 0.5, "restLength": 0.5, "A.p": "(0 0 0)", "B.p": "(0 0 1.2)"}
RUN = 1.0  # s of wall time before the signal


def main():
    spring = fmu_restraint("spring", fmu_path("linearSpring"), "hull", SPRING, report="off")
    case = Case("signalRows", rigid_body_model(rigid_body("hull", 2.0, 0.1, (0, 0, 0.6), "Pz"), spring,
                                               g=(0, 0, -9.81)), 1e6, 0.001)
    bodies = os.path.join(case.dir, "postProcessing", "rigidBodySim", "0", "bodies.dat")
    connector = os.path.join(case.dir, "postProcessing", "fmuConnectors", "0", "spring.dat")
    checks = []
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGKILL):
        subprocess.run(["rm", "-rf", os.path.join(case.dir, "postProcessing")], check=True)
        process = subprocess.Popen(["rigidBodySim", "-case", case.dir], stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL)
        time.sleep(RUN)
        process.send_signal(sig)
        code = process.wait()
        name = f"{sig.name} after {RUN} s"
        checks.append(check(f"{name}: the run ends by the signal", code == -sig, f"exit code {code}"))
        try:
            killed = sig == signal.SIGKILL
            body_rows, _ = whole_rows(bodies, cut_end=killed)
            connector_rows, _ = whole_rows(connector, cut_end=killed)
        except (PostProcessingError, OSError) as error:
            checks.append(check(f"{name}: whole rows only", False, str(error)))
            continue
        checks.append(check(f"{name}: whole rows only" + (" (a cut last row left out)" if killed else ""), True,
                            f"bodies {body_rows} rows, connector {connector_rows}"))
        # bodies.dat has the start row besides a row per completed step
        steps = body_rows - 1
        allowed = 1 if sig != signal.SIGKILL else 1 + int(0.3 * steps / RUN)
        checks.append(check(
            f"{name}: the connector keeps the completed steps (at most {allowed} fewer)",
            steps - allowed <= connector_rows <= steps,
            f"{steps} steps completed, {connector_rows} connector rows"))
    failures = sum(checks)
    if not failures:
        case.cleanup()
    return summary(len(checks), failures)


if __name__ == "__main__":
    sys.exit(main())

"""A kill while a time is written loses no connector row that the bodies'
file has: the connector's row of a step is on disk before the step's time
folder is written.

rigidBodySim and sixDoFSim write the bodies' row of a step when its last
solve is done, then the time (OpenFOAM's uniform/time first, then the
registered objects, among them the connector's output). Here uniform/time
of 0.5 is a named pipe, so the run blocks in its open, and is killed with
SIGKILL there: the bodies' file has the row of 0.5, and so must the
connector's file. Before the connector wrote its row at a write time's
first solve, the row waited for the write of the time (or the next step)
and the kill lost it.

Each step is solved three times (-nIter 3) with OpenFOAM's Newmark solver,
whose solves of a step differ (each uses the accelerations of the one
before), so a row written at the first solve of 0.5 must be replaced by
the last one's: the rows of the killed run, 0 to 0.5, are compared as text
with those of an uninterrupted run that writes no time before its end
(each row written when the next step begins), which must be identical
(same program, same inputs, same order of operations: bit for bit).
"""
import os
import signal
import subprocess
import sys
import time

from foamfmi.bridgecase import Case, check, fmu_path, fmu_restraint, rigid_body, rigid_body_model, summary
from foamfmi.sixdofcase import SixDoFCase, sixdof_body
from foamfmi.sixdofcase import fmu_restraint as sixdof_fmu_restraint

END, DT, WRITE, KILL_TIME = 1.0, 0.01, 0.25, "0.5"
SPRING = {"stiffness": 50, "damping": 0.5, "restLength": 0.5, "A.p": (0, 0, 0), "B.p": (0, 0, 1.2)}


def rigid_case(name, write_interval=WRITE):
    spring = fmu_restraint("spring", fmu_path("linearSpring"), "hull", SPRING, report="off")
    model = rigid_body_model(rigid_body("hull", 2.0, 0.1, (0, 0, 0.6), "Pz"), spring,
                             solver="Newmark", g=(0, 0, -9.81))
    return Case(name, model, END, DT, write_interval=write_interval)


def sixdof_case(name, write_interval=WRITE):
    spring = sixdof_fmu_restraint("spring", fmu_path("linearSpring"), "hull", SPRING)
    return SixDoFCase(name, {"hull": sixdof_body(2.0, 0.1, (0.0, 0.0, 0.6), "Newmark", spring)},
                      END, DT, write_interval=write_interval, g=(0, 0, -9.81))


def rows(path, last):
    """The data rows of a table up to time last, as text."""
    try:
        with open(path) as f:
            return [line for line in f
                    if not line.startswith("#") and float(line.split()[0]) < last + DT / 2]
    except OSError:
        return []


def killed_in_write(case, program, bodies):
    """Run program on case with uniform/time of KILL_TIME a named pipe; kill
    it with SIGKILL once the bodies' row of KILL_TIME is written (the run
    then blocks in the open of the pipe). Returns the exit code."""
    folder = os.path.join(case.dir, KILL_TIME, "uniform")
    os.makedirs(folder)
    os.mkfifo(os.path.join(folder, "time"))
    process = subprocess.Popen([program, "-case", case.dir, "-nIter", "3"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT,
                               start_new_session=True)
    deadline = time.time() + 60
    while process.poll() is None and time.time() < deadline:
        if rows(bodies, float(KILL_TIME))[-1:] and \
                abs(float(rows(bodies, float(KILL_TIME))[-1].split()[0]) - float(KILL_TIME)) < DT / 2:
            time.sleep(0.5)  # blocked in the open of the pipe by now
            break
        time.sleep(0.05)
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGKILL)
    return process.wait()


def main():
    checks, failures = 0, 0
    for program, make, driver in [("rigidBodySim", rigid_case, "rigidBodySim"),
                                  ("sixDoFSim", sixdof_case, "sixDoFSim")]:
        # No write time before the end: every row written when the next
        # step begins, after the step's last solve
        reference = make(program + ".reference", 10 * END)
        reference.run(n_iter=3)
        killed = make(program + ".killed")
        code = killed_in_write(killed, program,
                               os.path.join(killed.dir, "postProcessing", driver, "0", "bodies.dat"))
        last = float(KILL_TIME)
        table = ("postProcessing", "fmuConnectors", "0", "spring.dat")
        bodies = rows(os.path.join(killed.dir, "postProcessing", driver, "0", "bodies.dat"), last)
        connector = rows(os.path.join(killed.dir, *table), last)
        expected = rows(os.path.join(reference.dir, *table), last)
        # 50 steps of 0.01 to 0.5; bodies.dat has the start row too
        results = [
            check(f"{program}: killed while writing t = {KILL_TIME}", code == -signal.SIGKILL,
                  f"exit code {code}"),
            check(f"{program}: the bodies' file has the row of {KILL_TIME}",
                  len(bodies) == 51, f"{len(bodies)} rows, 0 to {bodies[-1].split()[0] if bodies else None}"),
            check(f"{program}: the connector's file has every row the bodies' file has",
                  len(connector) == len(bodies) - 1,
                  f"{len(connector)} rows, last t = {connector[-1].split()[0] if connector else None}"),
            check(f"{program}: they are the rows of the uninterrupted run (the last solve's, "
                  "not the first's)", connector == expected,
                  "identical" if connector == expected else
                  f"first difference at row {next((i for i, (a, b) in enumerate(zip(connector, expected)) if a != b), min(len(connector), len(expected)))}"),
        ]
        checks += len(results)
        failures += sum(results)
        if not sum(results):
            reference.cleanup()
            killed.cleanup()
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())

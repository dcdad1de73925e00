"""A run that ends abnormally keeps every row of every completed time step,
in the connector's output and in the driver's bodies file; a connector that
asks to end the simulation ends it with its reason.

Rows reach their files when their step completes: the driver writes and
flushes its bodies row after the step's last solve, the connector its row
when the next step begins, before the FMU is called. So nothing waits in
memory for a write time (none is reached here: writeInterval lies beyond
the end) and a FatalError, a crash and kill -9 keep the same rows. The test
FMU faultySpring (testSpring with fault parameters, tests/fmusim/fixtures)
misbehaves in the step that starts at its fault time:

- nanTime 0.3: A.F[1] is NaN after the step from 0.3 to 0.31, a FatalError
  naming the output; the steps to 0.3 completed. (Before, the connector's
  rows stopped at 0.29: the row of 0.3 was written only when the next
  step's evaluation had succeeded; and bodies.dat was empty.) A second
  connector after it, which the error reaches before its evaluation of the
  failed step, keeps its row of 0.3 too (the exit handler writes it).
- endTime 0.3: the step from 0.3 is refused with fmi2Discard and
  fmi2Terminated (FMI 2.0's way for a co-simulation FMU to end the
  simulation): a FatalError that says so and gives the FMU's reason.
- crashTime 0.07: the step from 0.07 writes through a null pointer; the
  rows of the 7 completed steps are kept (before: none, and bodies.dat
  empty).
- hangTime 0.09: the step from 0.09 never returns; the run is killed with
  SIGKILL once it hangs. Kept: the 9 completed steps (the last write time
  was 0.08), and the line shapes of catenary.fmu written at the write
  times before (VTK files and the series that lists them). The same for sixDoFSim's bodies file (nanTime).
"""
import json
import os
import signal
import subprocess
import sys
import time

from foamfmi.bridgecase import Case, fmu_path, fmu_restraint, rigid_body, rigid_body_model, summary
from foamfmi.sixdofcase import SixDoFCase, sixdof_body
from foamfmi.sixdofcase import fmu_restraint as sixdof_fmu_restraint

DT, FAULT_TIME, END = 0.01, 0.3, 1.0


def faulty_fmu():
    fmu = os.path.join(os.environ["FOAMFMI_BUILD_DIR"], "tests", "fixture-fmus", "faultySpring.fmu")
    if not os.path.isfile(fmu):
        raise SystemExit(f"{fmu} is missing: build the test fixtures first (./Allwmake)")
    return fmu


def catenary_line():
    """A slack catenary from the weight to an anchor on the seabed: a
    connector with a line shape, written as VTK at write times."""
    return fmu_restraint("line", fmu_path("catenary"), "weight", {
        "unstretchedLength": 3, "EA": "1e5", "weight": 0.5, "seabedContact": 1,
        "A.p": (0, 0, 0), "B.p": (2, 0, -1.5)})


def model(fmu, fault="nanTime", fault_time=FAULT_TIME, extra=""):
    spring = fmu_restraint("spring", fmu, "weight", {
        "stiffness": 100, "restLength": 0.5, fault: fault_time, "A.p": (0, 0, 0), "B.p": (0, 0, 0.5)})
    return rigid_body_model(rigid_body("weight", 1.0, 0.1, (0, 0, 0), "Pz"), spring + extra,
                            g=(0, 0, -9.81))


def steady_spring():
    """A second connector, evaluated after the faulty one."""
    return fmu_restraint("steady", fmu_path("linearSpring"), "weight", {
        "stiffness": 1, "restLength": 0.5, "A.p": (0, 0, 0), "B.p": (0, 0, 0.5)})


def steps_to(t):
    """Ends of the completed steps of DT up to t."""
    return [DT * (i + 1) for i in range(int(round(t / DT)))]


def rows_check(name, rows, expected):
    """(ok, message) for rows of times against expected ones. Times are
    sums of 0.01: compared with half a step of slack."""
    ok = len(rows) == len(expected) and all(abs(a - b) < DT / 2 for a, b in zip(rows, expected))
    return ok, (f"{name}: {len(rows)} rows, last t = {rows[-1] if rows else None}, "
                f"expected {len(expected)} up to t = {expected[-1] if expected else None:g}")


def table_or_empty(read):
    try:
        return read()["Time"]
    except (OSError, TypeError, KeyError):
        return []


def check_rows(label, case, last, connectors=("spring",)):
    """Failures among: connector rows to last, bodies rows 0 to last."""
    failures = 0
    checks = [rows_check(f"connector {c}", table_or_empty(lambda: case.connector(c)), steps_to(last))
              for c in connectors]
    checks.append(rows_check("bodies.dat", table_or_empty(case.bodies), [0.0] + steps_to(last)))
    for ok, message in checks:
        print(f"{'PASS' if ok else 'FAIL'} {label}, rows kept: {message}", flush=True)
        failures += 0 if ok else 1
    return failures


def run_killed(case, rows_before_kill, timeout=120):
    """Start rigidBodySim, wait until the connector has written the given
    number of rows (the run then hangs in the next step), kill it with
    SIGKILL, and return its exit code."""
    log = open(os.path.join(case.dir, "log.rigidBodySim"), "w")
    process = subprocess.Popen(["rigidBodySim", "-case", case.dir], stdout=log,
                               stderr=subprocess.STDOUT, start_new_session=True)
    output = os.path.join(case.dir, "postProcessing", "fmuConnectors", "0", "spring.dat")
    deadline = time.time() + timeout
    while process.poll() is None and time.time() < deadline:
        if len(table_or_empty(lambda: case.connector("spring"))) >= rows_before_kill and os.path.isfile(output):
            time.sleep(0.5)  # hanging in the next step by now
            break
        time.sleep(0.1)
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGKILL)
    code = process.wait()
    log.close()
    return code


def check_series(case, write_times):
    """Failures: the VTK series lists one complete file per write time."""
    folder = os.path.join(case.dir, "VTK", "fmuConnectors")
    try:
        with open(os.path.join(folder, "line.vtk.series")) as f:
            files = json.load(f)["files"]
    except (OSError, ValueError) as error:
        print(f"FAIL VTK series after the kill: {error}")
        return 1
    times = [entry["time"] for entry in files]
    complete = all(
        os.path.isfile(os.path.join(folder, entry["name"]))
        and open(os.path.join(folder, entry["name"])).read().count("\n") > 5
        for entry in files
    )
    ok = complete and len(times) == len(write_times) and all(
        abs(a - b) < DT / 2 for a, b in zip(times, write_times))
    print(f"{'PASS' if ok else 'FAIL'} VTK series after the kill: times {times}, "
          f"files {'complete' if complete else 'missing or cut'}")
    return 0 if ok else 1


def main():
    fmu = faulty_fmu()
    failures = 0

    # A NaN output: FatalError in the step from 0.3 to 0.31
    case = Case("fatalOutput", model(fmu, extra=steady_spring()), END, DT, write_interval=10 * END)
    log = case.run(expect_failure=True)
    stopped = "output A.F[1] is not finite" in log
    print(f"{'PASS' if stopped else 'FAIL'} the NaN force stops the run: "
          f"{'FatalError names A.F[1]' if stopped else log[-1500:]}")
    failures += (0 if stopped else 1) + check_rows("NaN output", case, FAULT_TIME, ("spring", "steady"))
    case.cleanup()

    # The connector ends the simulation
    case = Case("endRequest", model(fmu, "endTime"), END, DT, write_interval=10 * END)
    log = case.run(expect_failure=True)
    expected = ("restraint spring: the connector asks to end the simulation at t = 0.3",
                "the spring asks to end the simulation at endTime = 0.3 s")
    ended = all(e in log for e in expected)
    print(f"{'PASS' if ended else 'FAIL'} the connector ends the simulation at its endTime: "
          f"message {'found' if ended else 'missing'}" + ("" if ended else "\n" + log[-1500:]))
    failures += (0 if ended else 1) + check_rows("end request", case, FAULT_TIME)
    case.cleanup()

    # A crash of the FMU in the step from 0.07
    case = Case("crashOutput", model(fmu, "crashTime", 0.07), END, DT, write_interval=10 * END)
    case.run(expect_failure=True)
    failures += check_rows("crash", case, 0.07)
    case.cleanup()

    # kill -9 while the FMU hangs in the step from 0.09; a line shape
    # written every 0.02 s
    case = Case("killOutput", model(fmu, "hangTime", 0.09, catenary_line()), END, DT,
                write_interval=0.02)
    code = run_killed(case, 9)
    killed = code == -signal.SIGKILL
    print(f"{'PASS' if killed else 'FAIL'} killed while hanging: exit code {code}")
    failures += (0 if killed else 1) + check_rows("kill -9", case, 0.09)
    failures += check_series(case, [0.02, 0.04, 0.06, 0.08])
    case.cleanup()

    # sixDoFSim's bodies file: a NaN output in the step from 0.3
    spring = sixdof_fmu_restraint("spring", fmu, "weight", {
        "stiffness": 100, "restLength": 0.5, "nanTime": FAULT_TIME, "A.p": (0, 0, 0), "B.p": (0, 0, 0.5)})
    case = SixDoFCase("fatalOutputSixDoF", {"weight": sixdof_body(1.0, 0.1, (0, 0, 0), "symplectic", spring)},
                      END, DT, write_interval=10 * END, g=(0, 0, -9.81))
    case.run(expect_failure=True)
    failures += check_rows("sixDoFSim, NaN output", case, FAULT_TIME)
    case.cleanup()

    checks = 15
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())

"""Cost of one restraint evaluation: the linearSpring FMU through the
fmuConnector restraint against OpenFOAM's built-in linearSpring, the
same FMU with isolation process (in a process of its own), and its FMI 3.0
FMU (build/fmus/fmi3) in both isolations beside the FMI 2.0 one, measured
side by side in one run of restraintCost, printed as ratios and
differences, with the goal of a new step (within 2.5x of the built-in
restraint) and the machine's load while measured.

Run in the project's environment: tests/run-with-openfoam python3 bench/restraintCost/run.py
"""
import os
import subprocess
import sys

from foamfmi import cli
from foamfmi.bridgecase import Case, linear_spring, rigid_body, rigid_body_model, spring_fmu

# The goal of a new step: at most this times the built-in restraint's
NEW_STEP_GOAL = 2.5

# The spring of tests/bridge/test_spring_world.py on one floating body
SPRING = ((0.3, 0.2, 1.2), (0.1, 0, 0.05), 50, 0.5, 0.5)


def model():
    """The built-in spring and the FMU's four ways on one body."""
    return rigid_body_model(
        rigid_body("hull", 2, 0.1, (0, 0, 0), "floating"),
        linear_spring("builtin", "hull", *SPRING)
        + spring_fmu("fmu", "hull", *SPRING, isolation="none")
        + spring_fmu("fmuProcess", "hull", *SPRING, isolation="process")
        + spring_fmu("fmu3", "hull", *SPRING, fmu="fmi3/linearSpring", isolation="none")
        + spring_fmu("fmu3Process", "hull", *SPRING, fmu="fmi3/linearSpring", isolation="process"),
        g=None)


def main(argv):
    cli.parser("run.py", __doc__).parse_args(argv)
    load = os.getloadavg()[0]
    print(f"Load average {load:.2f} on {os.cpu_count()} cores while measured"
          + (": a loaded machine, the times are longer than on a quiet one"
             if load > 0.5 else ""))
    case = Case("restraintCost", model(), 1, 0.001)
    out = subprocess.run(
        ["restraintCost", "-case", case.dir, "-evaluations", "20000", "-rounds", "5"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, check=True,
    ).stdout
    case.cleanup()
    rows = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 11 and parts[0] in ("builtin", "fmu", "fmuProcess", "fmu3", "fmu3Process"):
            rows[parts[0]] = [float(x) for x in parts[2:]]
    b, f, p = rows["builtin"], rows["fmu"], rows["fmuProcess"]
    f3, p3 = rows["fmu3"], rows["fmu3Process"]
    print("Cost of one restraint evaluation, ns (fastest of 5 rounds of 20000):")
    print("                                  new step  repeated solve  new step, CPU of:")
    print("                                                            all threads  solver thread")
    print(f"  built-in linearSpring           {b[0]:8.0f}  {b[1]:8.0f}        {b[5]:8.0f}     {b[7]:8.0f}")
    print(f"  linearSpring FMU (fmuConnector) {f[0]:8.0f}  {f[1]:8.0f}        {f[5]:8.0f}     {f[7]:8.0f}")
    print(f"  ratio FMU / built-in            {f[0] / b[0]:8.1f}  {f[1] / b[1]:8.1f}        "
          f"{f[5] / b[5]:8.1f}     {f[7] / b[7]:8.1f}")
    print("The new step is the solver's wait (wall time): with no core free for the")
    print("writer thread it includes the writer's share of the solver's core.")
    print("The FMU's new step, part by part (each timed on its own, same rounds):")
    print(f"  evaluation (inputs, fmi2DoStep, outputs) {f[2]:6.0f}")
    print(f"    of which the traps masked and restored {f[8]:6.0f}  (x87 and SSE, once)")
    print(f"  state save (fmi2GetFMUstate, reused)     {f[3]:6.0f}")
    print(f"  row of outputs (17 values), solver       {f[4]:6.0f}")
    print(f"  sum                                      {sum(f[2:5]):6.0f}")
    print(f"  row of outputs, CPU of all threads       {f[6]:6.0f}  (formatted and written)")
    ratio = f[0] / b[0]
    thread = f[7] / b[7]
    verdict = {True: "met", False: "NOT met"}
    print(f"Goal: a new step within {NEW_STEP_GOAL}x of the built-in restraint")
    print(f"  the solver's wait {ratio:.2f}x: {verdict[ratio <= NEW_STEP_GOAL]}"
          f" (CPU of all threads {f[5] / b[5]:.2f}x)")
    print(f"  the solver thread's CPU {thread:.2f}x: {verdict[thread <= NEW_STEP_GOAL]}"
          " (its wait when a core is free for the writer thread)")
    print("A repeated solve restores the state, steps the FMU and reads its outputs.")
    print("The solver copies a step's row (the time and 17 values) into a ring; the")
    print("process's writer thread formats it (std::to_chars, shortest round trip) and")
    print("writes the rows of every 2 ms in one write(2). Rows are on disk before a")
    print("write time's folder, at a FatalError, a crash, a signal or a time-out; a")
    print("kill -9 loses at most the last 2 ms of rows (docs/restraint.md).")
    print()
    print("The same FMU in a process of its own (isolation process), ns:")
    print("                                  new step  repeated solve")
    print(f"  isolation none (in process)     {f[0]:8.0f}  {f[1]:8.0f}")
    print(f"  isolation process               {p[0]:8.0f}  {p[1]:8.0f}")
    print(f"  difference                      {p[0] - f[0]:8.0f}  {p[1] - f[1]:8.0f}")
    print("Goal: isolation process within 10000 ns of in process (on an idle machine)")
    print(f"  new step {'met' if p[0] - f[0] <= 10000 else 'NOT met'}, "
          f"repeated solve {'met' if p[1] - f[1] <= 10000 else 'NOT met'}")
    print()
    print("The same connector as an FMI 3.0 FMU (fmi3/linearSpring.fmu: whole")
    print("arrays through fmi3Get/SetFloat64) beside the FMI 2.0 FMU, ns:")
    print("                                  new step  repeated solve")
    print(f"  FMI 2.0, isolation none         {f[0]:8.0f}  {f[1]:8.0f}")
    print(f"  FMI 3.0, isolation none         {f3[0]:8.0f}  {f3[1]:8.0f}")
    print(f"  difference                      {f3[0] - f[0]:8.0f}  {f3[1] - f[1]:8.0f}")
    print(f"  FMI 2.0, isolation process      {p[0]:8.0f}  {p[1]:8.0f}")
    print(f"  FMI 3.0, isolation process      {p3[0]:8.0f}  {p3[1]:8.0f}")
    print(f"  difference                      {p3[0] - p[0]:8.0f}  {p3[1] - p[1]:8.0f}")
    print(f"  FMI 3.0 parts: evaluation {f3[2]:.0f}, state save {f3[3]:.0f}, "
          f"row {f3[4]:.0f} (FMI 2.0: {f[2]:.0f}, {f[3]:.0f}, {f[4]:.0f})")


if __name__ == "__main__":
    main(sys.argv[1:])

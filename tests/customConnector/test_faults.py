"""A connector FMU that misbehaves never takes the run down unnamed.

faultyBungee-<fault>.fmu is the example's bungee with a fault in the first
fmi2DoStep from t = 0.25 s on (tests/customConnector/faultyBungee.c):
segfault, divide-by-zero, abort, hang, exit (exit(0)). A 2 kg weight
hangs on it from the world in rigidBodySim, steps of 1/64 s (exact in
binary, so the fault is at t = 0.25 exactly).

- In the solver's process (isolation none, the default): a crash prints
  "--> FOAM FATAL ERROR: the FMU crashed (<signal>) in fmi2DoStep at
  t = 0.25 in FMU '<file>' of restraint bungee" before the solver dies,
  and OpenFOAM's own stack trace still follows for SIGSEGV and SIGFPE
  (the handler chains to it); exit(0) is named too and the run does not
  end with status 0; a hang ends after timeout with a line that says so.
- In a process of its own (isolation process): each fault, the hang with
  timeout 1, is a FatalError naming the restraint, the FMU, the fmi2
  function and the time; the completed steps' rows are kept.
- The same in sixDoFSim, for the sixDoFRigidBodyMotion restraint.
- The bungee without faults gives the same motion and connector output, bit
  for bit, in either isolation.

    python3 test_faults.py
"""
import os
import sys
import time

from foamfmi.bridgecase import Case, rigid_body, vec
from foamfmi.sixdofcase import SixDoFCase, sixdof_body

DT, END, FAULT_TIME = 1.0 / 64, 0.5, 0.25
SIGNALS = {
    "segfault": "SIGSEGV, segmentation fault",
    "divide-by-zero": "SIGFPE, arithmetic exception",
    "abort": "SIGABRT, abort",
}


def faulty(fault):
    path = os.path.join(os.environ["FOAMFMI_BUILD_DIR"], "tests", "fixture-fmus", f"faultyBungee-{fault}.fmu")
    if not os.path.isfile(path):
        raise SystemExit(f"{path} is missing: build the test fixtures first (./Allwmake)")
    return path


def entries(isolation, timeout):
    text = f"isolation {isolation};" if isolation else ""
    return text + (f" timeout {timeout};" if timeout else "")


def model(fmu, isolation="", timeout=0):
    return f"""
    solver {{ type symplectic; }}
    g (0 0 -9.81);
    bodies
    {{
{rigid_body("weight", 2.0, 0.1, (0, 0, -1.2), "Pz")}
    }}
    restraints
    {{
        bungee
        {{
            type fmuConnector;
            body weight;
            fmu "{fmu}";
            {entries(isolation, timeout)}
            parameters
            {{
                stiffness 100;
                restLength 1;
                A.p {vec((0, 0, 0))};
                B.p {vec((0, 0, 0))};
            }}
        }}
    }}
"""


def sixdof_bodies(fmu, isolation, timeout):
    restraint = f"""            bungee
            {{
                sixDoFRigidBodyMotionRestraint fmuConnector;
                fmu "{fmu}";
                body weight;
                {entries(isolation, timeout)}
                parameters
                {{
                    stiffness 100; restLength 1;
                    A.p {vec((0, 0, 0))}; B.p {vec((0, 0, 0))};
                }}
            }}
"""
    return {"weight": sixdof_body(2.0, 0.1, (0, 0, -1.2), restraints=restraint)}


class Checks:
    def __init__(self):
        self.failures = 0
        self.count = 0

    def check(self, ok, what, log=""):
        self.count += 1
        self.failures += 0 if ok else 1
        print(f"{'PASS' if ok else 'FAIL'} {what}" + ("" if ok or not log else "\n" + log[-2500:]))


def run(case):
    start = time.monotonic()
    log = case.run(expect_failure=True)
    return log, time.monotonic() - start


def in_process(checks):
    for fault, signal in SIGNALS.items():
        fmu = faulty(fault)
        case = Case(f"faultInProcess.{fault}", model(fmu), END, DT)
        log, _ = run(case)
        report = (f"--> FOAM FATAL ERROR: the FMU crashed ({signal}) in fmi2DoStep at t = {FAULT_TIME:g} "
                  f"in FMU '{fmu}' of restraint bungee")
        ok = report in log
        handler = {"segfault": "Foam::sigSegv::sigHandler", "divide-by-zero": "Foam::sigFpe::sigHandler"}.get(fault)
        if handler:
            ok = ok and handler in log and log.index(report) < log.index(handler)
        checks.check(ok, f"in process, {fault}: the crash is named"
                     + (", then OpenFOAM's stack trace" if handler else ""), log)
        case.cleanup()

    fmu = faulty("exit")
    case = Case("faultInProcess.exit", model(fmu), END, DT)
    log, _ = run(case)
    ok = f"--> FOAM FATAL ERROR: the FMU exited (status 0) in fmi2DoStep at t = {FAULT_TIME:g} in FMU '{fmu}' " \
         "of restraint bungee" in log
    checks.check(ok, "in process, exit(0): named, and the run's status is not 0", log)
    case.cleanup()

    fmu = faulty("hang")
    case = Case("faultInProcess.hang", model(fmu, timeout=1), END, DT)
    log, seconds = run(case)
    ok = (f"--> FOAM FATAL ERROR: time-out: fmi2DoStep at t = {FAULT_TIME:g} in FMU '{fmu}' of restraint bungee "
          "did not return within 1 s (the restraint's timeout entry)" in log) and seconds < 30
    checks.check(ok, f"in process, hang with timeout 1: ended after {seconds:.1f} s, named", log)
    case.cleanup()


def in_own_process(checks):
    for fault in ("segfault", "divide-by-zero", "abort", "exit", "hang"):
        fmu = faulty(fault)
        case = Case(f"faultIsolated.{fault}", model(fmu, "process", 1 if fault == "hang" else 0), END, DT)
        log, seconds = run(case)
        call = f"fmi2DoStep at t = {FAULT_TIME:g}"
        what = {
            "exit": f"the FMU exited (status 0) in {call}",
            "hang": f"time-out: {call}",
        }.get(fault, f"the FMU crashed ({SIGNALS.get(fault)}) in {call}")
        ok = "FOAM FATAL ERROR" in log and f"restraint bungee at t = {FAULT_TIME + DT:g}: {what} in FMU '{fmu}' " \
             "of restraint bungee" in log
        rows = case.connector("bungee")["Time"]
        kept = len(rows) == round(FAULT_TIME / DT)
        checks.check(ok and kept and seconds < 30,
                     f"isolation process, {fault}: a FatalError naming the call, {len(rows)} rows kept", log)
        case.cleanup()

    fmu = faulty("segfault")
    case = SixDoFCase("faultIsolatedSixDoF", sixdof_bodies(fmu, "process", 0), END, DT, g=(0, 0, -9.81))
    log, _ = run(case)
    ok = "FOAM FATAL ERROR" in log and "the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep at t = " \
         f"{FAULT_TIME:g} in FMU '{fmu}' of restraint bungee" in log
    checks.check(ok, "sixDoF, isolation process, segfault: a FatalError naming the call", log)
    case.cleanup()

    case = SixDoFCase("faultInProcessSixDoF", sixdof_bodies(fmu, "", 0), END, DT, g=(0, 0, -9.81))
    log, _ = run(case)
    ok = f"--> FOAM FATAL ERROR: the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep at t = {FAULT_TIME:g} " \
         f"in FMU '{fmu}' of restraint bungee" in log
    checks.check(ok, "sixDoF, in process, segfault: the crash is named", log)
    case.cleanup()


def same_either_way(checks):
    """Before the fault the faulty bungee is the bungee: up to 0.25 s the two
    isolations give identical files."""
    fmu = faulty("exit")
    results = {}
    for isolation in ("none", "process"):
        case = Case(f"isolation.{isolation}", model(fmu, isolation), FAULT_TIME - DT / 2, DT)
        case.run()
        with open(os.path.join(case.dir, "postProcessing", "fmuConnectors", "0", "bungee.dat")) as f:
            connector = f.read()
        with open(os.path.join(case.dir, "postProcessing", "rigidBodySim", "0", "bodies.dat")) as f:
            bodies = f.read()
        results[isolation] = (connector, bodies)
        case.cleanup()
    checks.check(results["none"] == results["process"] and results["none"][0].count("\n") > 10,
                 "isolation none and process: identical connector and body files")


def main():
    checks = Checks()
    in_process(checks)
    in_own_process(checks)
    same_either_way(checks)
    print(f"{checks.count - checks.failures} passed, {checks.failures} failed")
    return 1 if checks.failures else 0


if __name__ == "__main__":
    sys.exit(main())

"""A run restarted from a written time reproduces the uninterrupted run.

The two-body spring model runs from 0 to 1 s, writing at 0.5 s: the
rigid-body state (uniform/rigidBodyMotionState) and the connector FMU's
serialized state (uniform/fmuConnectors/spring). A copy of the case
restarted from 0.5 s must give the same motion to round-off, and the
connector's output series must continue where it left off.
"""
import os
import shutil
import subprocess
import sys

from foamfmi.bridgecase import Case, summary
from test_two_bodies import model


def restart_from_half(full, name, edit=lambda text: text, keep_state=True):
    """A copy of the case restarted from 0.5 s, its model edited by edit and
    the connector's state file removed unless keep_state; returns (case,
    rigidBodySim's exit code, log)."""
    case = Case(name, edit(model("symplectic")), 1.0, 0.005, write_interval=0.5)
    shutil.copytree(os.path.join(full.dir, "0.5"), os.path.join(case.dir, "0.5"))
    if not keep_state:
        os.remove(os.path.join(case.dir, "0.5", "uniform", "fmuConnectors", "spring"))
    case.set_time(0.5, 1.0, 0.005, 0.5)
    result = subprocess.run(
        ["rigidBodySim", "-case", case.dir, "-nIter", "2"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
    )
    return case, result.returncode, result.stdout


def restart_variants(full):
    """(name, ok, detail) of restarts that must not pass silently."""
    results = []

    # The bodies continue from 0.5 s; a connector starting anew would not
    case, code, log = restart_from_half(full, "restart.missing", keep_state=False)
    ok = code != 0 and all(
        s in log for s in ("restraint spring", "connector's state", "is missing", "restart fresh")
    )
    results.append(("missing state file is fatal", ok, f"exit code {code}"))
    case.cleanup()

    # ... unless the restraint asks for it
    def fresh(text):
        return text.replace("type fmuConnector;", "type fmuConnector; restart fresh;")

    case, code, log = restart_from_half(full, "restart.fresh", fresh, keep_state=False)
    rows = case.connector("spring", start="0.5")["Time"] if code == 0 else []
    results.append(("restart fresh runs without a state", code == 0 and len(rows) == 100,
                    f"exit code {code}, {len(rows)} rows"))
    case.cleanup()

    # A changed parameter cannot reach an FMU whose state brings the old
    # one back: the user is told which, with both values
    def stiffer(text):
        return text.replace("stiffness 50.0;", "stiffness 80.0;")

    case, code, log = restart_from_half(full, "restart.changed", stiffer)
    ok = code == 0 and "parameters differ from the state" in log and "stiffness 80" in log and "50" in log
    results.append(("changed parameter reported", ok, f"exit code {code}"))
    case.cleanup()
    return results


def main():
    failures = checks = 0
    case = Case("restart", model("symplectic"), 1.0, 0.005, write_interval=0.5)
    case.run(n_iter=2)
    full = case.bodies()

    state_file = os.path.join(case.dir, "0.5", "uniform", "fmuConnectors", "spring")
    checks += 1
    if not os.path.isfile(state_file):
        failures += 1
        print(f"FAIL state file: {state_file} was not written")
    else:
        print(f"PASS state file: {state_file}")

    restarted = Case("restart.from05", model("symplectic"), 1.0, 0.005, write_interval=0.5)
    shutil.copytree(os.path.join(case.dir, "0.5"), os.path.join(restarted.dir, "0.5"))
    restarted.set_time(0.5, 1.0, 0.005, 0.5)
    log = restarted.run(n_iter=2)
    checks += 1
    if "FMU state restored at t = 0.5" not in log:
        failures += 1
        print("FAIL restore: the log does not report the FMU state being restored")
    else:
        print("PASS restore: FMU state restored at t = 0.5")

    part = restarted.bodies(start="0.5")
    # Times accumulate round-off (0.5 is written as 0.50000000000000033)
    offset = min(range(len(full["Time"])), key=lambda i: abs(full["Time"][i] - 0.5))
    # Same operations on the same numbers: the written state has 17
    # significant digits, so the two runs agree to a few ulps.
    worst = max(
        abs(part[q][i] - full[q][offset + i])
        for q in ("body1.c.x", "body2.c.x", "body1.v.x", "body2.v.x")
        for i in range(len(part["Time"]))
    )
    checks += 1
    if len(part["Time"]) != len(full["Time"]) - offset or worst > 1e-13:
        failures += 1
        print(f"FAIL motion after restart: max difference {worst:.2e}, "
              f"{len(part['Time'])} rows for {len(full['Time']) - offset}")
    else:
        print(f"PASS motion after restart: max difference {worst:.2e}")

    out_full = case.connector("spring")
    out_part = restarted.connector("spring", start="0.5")
    n = len(out_part["Time"])
    diff = max(abs(a - b) for a, b in zip(out_part["A.F[1]"], out_full["A.F[1]"][-n:]))
    checks += 1
    tdiff = max(abs(a - b) for a, b in zip(out_part["Time"], out_full["Time"][-n:]))
    if tdiff > 1e-12 or diff > 1e-10:
        failures += 1
        print(f"FAIL connector output after restart: max difference {diff:.2e}")
    else:
        print(f"PASS connector output after restart: {n} rows, max difference {diff:.2e} N")

    for name, ok, detail in restart_variants(case):
        checks += 1
        failures += 0 if ok else 1
        print(f"{'PASS' if ok else 'FAIL'} {name}: {detail}")

    case.cleanup()
    restarted.cleanup()
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())

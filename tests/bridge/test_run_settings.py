"""The entries that say how an fmuConnector's FMU runs: isolation (none or
process), timeout (seconds per FMU call, 0: no limit) and sha256 (the
.fmu file's hash, which must match), in both restraints.

- Wrong values stop the run with a FatalIOError naming the restraint, the
  entry and what is expected: an unknown isolation with the valid ones, a
  negative timeout, a sha256 that is not 64 hexadecimal digits in quotes,
  a sha256 that is not the file's with both hashes (rigidBodySim and
  sixDoFSim).
- The file's own sha256 (in any case of letters) runs, and isolation
  process gives the spring's motion and outputs bit for bit as isolation
  none does; a run in one isolation restarts in the other, bit for bit.
"""
import hashlib
import os
import shutil
import sys

from foamfmi.bridgecase import Case, fmu_path, fmu_restraint, rigid_body, rigid_body_model, summary, vec
from foamfmi.sixdofcase import SixDoFCase, sixdof_body
from foamfmi.sixdofcase import fmu_restraint as sixdof_fmu_restraint

PARAMETERS = f"stiffness 50; damping 0.5; restLength 0.5; A.p {vec((0.1, 0, 0.05))}; B.p {vec((0.3, 0.2, 1.2))};"


def model(fmu, extra):
    return rigid_body_model(rigid_body("hull", 2, 0.1, (0, 0, 0), "floating"),
                            fmu_restraint("mooring", fmu, "hull", PARAMETERS, extra=extra),
                            g=(0, 0, -9.81))


def sixdof_bodies(fmu, extra):
    restraint = sixdof_fmu_restraint("mooring", fmu, "hull", PARAMETERS, extra=extra)
    return {"hull": sixdof_body(2.0, 0.1, (0, 0, 0), restraints=restraint)}


def main():
    spring = fmu_path("linearSpring")
    with open(spring, "rb") as f:
        actual = hashlib.sha256(f.read()).hexdigest()
    wrong = hashlib.sha256(b"another file").hexdigest()

    refused = {
        "unknown isolation": ("isolation thread;", ["isolation", "thread", "none", "process"]),
        "negative timeout": ("timeout -1;", ["restraint mooring: entry timeout is -1", ">= 0"]),
        # (64 hexadecimal digits without their quotes: OpenFOAM splits them
        # into a number and a word; a fixed value, because how it splits a
        # real hash depends on its digits: "7e5..." is a float, "7e500..."
        # an overflow that OpenFOAM's own parser stops at)
        "sha256 unquoted": ("sha256 7" + "a" * 63 + ";",
                            ["restraint mooring: entry sha256 must be the 64 hexadecimal digits",
                             "double quotes"]),
        "sha256 too short": ('sha256 "abc123";', ["restraint mooring: entry sha256", "64 hexadecimal digits"]),
        "sha256 of another file": (f'sha256 "{wrong}";',
                                   ["restraint mooring", spring, f"has SHA-256 {actual}",
                                    f"sha256 expects {wrong}", "native code"]),
    }
    failures, count = 0, 0
    for name, (extra, expected) in refused.items():
        for kind in ("rigidBody", "sixDoF"):
            if kind == "sixDoF" and name not in ("unknown isolation", "sha256 of another file"):
                continue
            case = (Case("runSettings", model(spring, extra), 0.1, 0.01) if kind == "rigidBody"
                    else SixDoFCase("runSettings", sixdof_bodies(spring, extra), 0.1, 0.01))
            log = case.run(expect_failure=True)
            missing = [e for e in expected if e not in log]
            count += 1
            failures += 1 if missing else 0
            print(f"{'FAIL' if missing else 'PASS'} {kind}, {name}: "
                  + (f"message lacks {missing}\n{log[-1500:]}" if missing else "refused"))
            case.cleanup()

    outputs = {}
    for name, extra in (("none", f'isolation none; sha256 "{actual.upper()}";'),
                        ("process", f'isolation process; timeout 10; sha256 "{actual}";')):
        case = Case("runSettings", model(spring, extra), 0.5, 0.01)
        case.run(n_iter=3)
        outputs[name] = (case.connector("mooring"), case.bodies())
        case.cleanup()
        case = SixDoFCase("runSettings", sixdof_bodies(spring, extra), 0.5, 0.01)
        case.run(n_iter=3)
        outputs[name + " sixDoF"] = (case.bodies(),)
        case.cleanup()
    for kind in ("", " sixDoF"):
        same = outputs["none" + kind] == outputs["process" + kind] and len(outputs["none" + kind][0]["Time"]) >= 50
        count += 1
        failures += 0 if same else 1
        print(f"{'PASS' if same else 'FAIL'}{kind or ' rigidBody'}: the file's sha256 runs; isolation process and "
              "none give the same outputs bit for bit (3 solves per step)")

    # The state written in the solver's process restores in a process of its
    # own: the restarted run continues the uninterrupted one bit for bit
    full = Case("runSettings", model(spring, ""), 1.0, 0.01, write_interval=0.5)
    full.run(n_iter=2)
    restarted = Case("runSettings", model(spring, "isolation process;"), 1.0, 0.01, write_interval=0.5)
    shutil.copytree(os.path.join(full.dir, "0.5"), os.path.join(restarted.dir, "0.5"))
    restarted.set_time(0.5, 1.0, 0.01, 0.5)
    restarted.run(n_iter=2)
    # The rows from 0.5 s (OpenFOAM restarts its time from the folder's name,
    # 0.5, where the sum of the steps is 0.5000000000000002)
    rows, whole = restarted.bodies(start="0.5"), full.bodies()
    n = len(rows["Time"])
    same = n == 51 and all(rows[name] == whole[name][-n:] for name in rows if name != "Time")
    count += 1
    failures += 0 if same else 1
    print(f"{'PASS' if same else 'FAIL'} restart: written with isolation none, continued with isolation process, "
          "bit for bit")
    full.cleanup()
    restarted.cleanup()

    return summary(count, failures)


if __name__ == "__main__":
    sys.exit(main())

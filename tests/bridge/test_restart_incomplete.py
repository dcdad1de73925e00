"""A restart from a time that was not written completely stops with a
FatalIOError that names the time, the file and the previous complete time;
it never starts the bodies or a connector over in silence.

A run to 1 s writes every 0.25 s: the rigid-body state
(uniform/rigidBodyMotionState), the connector's FMU state
(uniform/fmuConnectors/spring), implicitNewmark's memory
(uniform/implicitNewmark) and OpenFOAM's uniform/time. Copies of the case
keep 0.25 and 0.5, with 0.5 damaged as a stopped run leaves it, and restart
from the latest time (startFrom latestTime, as a user restarts):

- disk full: every file of 0.5 empty (before: exit code 0, the bodies and
  the connector back at their initial state, a header warning only);
- a state file deleted (before, for the rigid-body state: exit code 0, the
  bodies reset, the connector restored);
- a file cut in half, as a kill during the write left it before the
  project's files were written to a temporary name and renamed (before:
  OpenFOAM's parse error, or a header warning and a silent start);
- what a kill during a write leaves now: uniform/time and the first state
  files, a temporary file and no more; made real by a run killed with
  SIGKILL while it writes the connector's state of 0.5 into a named pipe.

Each must fail, name 0.5 and the damaged file (the first one a restart
reads: uniform/time, then the rigid-body state, the connector's, the
solver's) and point to 0.25. Then a
full disk for real: the connector's state of 0.5 written to /dev/full stops
the run with a FatalError naming the file, and the restart from 0.5 is the
same FatalIOError. The same checks for sixDoFSim's uniform/sixDoFBodies,
and for addedMassRigidBodyMotion's rigid-body state (moveDynamicMesh on the
box of test_added_mass_entries, in test mode): deleted, cut in half, and,
with the added-mass coupling on, without the added mass in use. And the
intact copies restart.
"""
import os
import shutil
import signal
import subprocess
import sys
import time

from foamfmi.implicitcase import ImplicitCase
import test_added_mass_entries as added_mass
from foamfmi.sixdofcase import SixDoFCase
from test_sixdof_spring_world import CENTRE, M, J, fmu_spring
from foamfmi.sixdofcase import sixdof_body
from test_two_bodies import model

END, DT, WRITE = 1.0, 0.005, 0.25
STATE = "uniform/rigidBodyMotionState"
CONNECTOR = "uniform/fmuConnectors/spring"
SOLVER = "uniform/implicitNewmark"
TIME = "uniform/time"


def latest_time(case):
    """startFrom latestTime in the case's controlDict."""
    path = os.path.join(case.dir, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text.replace("startFrom startTime;", "startFrom latestTime;"))


def run(case, program="rigidBodySim"):
    result = subprocess.run([program, "-case", case.dir], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    return result.returncode, result.stdout


def damaged_copy(full, name, damage, make=ImplicitCase, text=None):
    """A copy of the case with 0.25 and 0.5, 0.5 damaged by damage(dir of
    0.5), restarting from the latest time."""
    case = make(name, text if text is not None else model("implicitNewmark"), END, DT,
                write_interval=WRITE)
    for t in ("0.25", "0.5"):
        shutil.copytree(os.path.join(full.dir, t), os.path.join(case.dir, t))
    damage(os.path.join(case.dir, "0.5"))
    latest_time(case)
    return case


def empty(*files):
    def damage(folder):
        for f in files:
            open(os.path.join(folder, f), "w").close()
    return damage


def delete(*files):
    def damage(folder):
        for f in files:
            if os.path.exists(os.path.join(folder, f)):
                os.remove(os.path.join(folder, f))
    return damage


def halve(f):
    def damage(folder):
        path = os.path.join(folder, f)
        if not os.path.exists(path):
            return
        with open(path, "rb") as stream:
            data = stream.read()
        with open(path, "wb") as stream:
            stream.write(data[: len(data) // 2])
    return damage


def all_files(folder):
    return [os.path.relpath(os.path.join(d, f), folder) for d, _, fs in os.walk(folder) for f in fs]


def disk_full(folder):
    empty(*all_files(folder))(folder)


def after_kill(folder):
    """What a kill while writing the connector's state leaves now: OpenFOAM's
    uniform/time, half a temporary file, no state files."""
    delete(STATE, CONNECTOR, SOLVER)(folder)
    with open(os.path.join(folder, CONNECTOR + ".tmp"), "w") as stream:
        stream.write("FoamFile\n{\n    version 2.0;\n    format ascii;\n")


def check_refused(label, code, log, damaged, time="0.5", previous="0.25"):
    """(ok, detail): a FatalIOError that names the time, the file and the
    previous complete time."""
    path = os.path.join(time, *damaged.split("/"))
    expected = ["FOAM FATAL IO ERROR", path, f"t = {time}", f"previous complete time, {previous}"]
    missing = [e for e in expected if e not in log]
    ok = code != 0 and not missing
    detail = f"exit code {code}" + (f", missing {missing}:\n{log[-2500:]}" if missing else "")
    return ok, f"{label}: {detail}"


def killed_while_writing(name):
    """A run killed with SIGKILL while it writes the connector's state of
    0.5: the temporary file is a named pipe, so the write blocks there."""
    case = ImplicitCase(name, model("implicitNewmark"), END, DT, write_interval=WRITE)
    folder = os.path.join(case.dir, "0.5", "uniform", "fmuConnectors")
    os.makedirs(folder)
    os.mkfifo(os.path.join(folder, "spring.tmp"))
    process = subprocess.Popen(["rigidBodySim", "-case", case.dir], stdout=subprocess.DEVNULL,
                               stderr=subprocess.STDOUT, start_new_session=True)
    deadline = time.time() + 60
    while process.poll() is None and time.time() < deadline:
        if os.path.isfile(os.path.join(case.dir, "0.5", TIME)):
            time.sleep(0.5)  # blocked in the open of the pipe by now
            break
        time.sleep(0.05)
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGKILL)
    code = process.wait()
    os.remove(os.path.join(folder, "spring.tmp"))
    latest_time(case)
    return case, code


def disk_full_for_real(name):
    """A run whose connector state of 0.5 goes to /dev/full; returns the
    case and the run's exit code and log."""
    case = ImplicitCase(name, model("implicitNewmark"), END, DT, write_interval=WRITE)
    folder = os.path.join(case.dir, "0.5", "uniform", "fmuConnectors")
    os.makedirs(folder)
    os.symlink("/dev/full", os.path.join(folder, "spring.tmp"))
    code, log = run(case)
    latest_time(case)
    return case, code, log


def sixdof_checks():
    """(ok, detail) of sixDoFSim restarts from a damaged 0.5."""
    bodies = {"fmu": sixdof_body(M, J, CENTRE, "Newmark", fmu_spring("fmu"))}
    full = SixDoFCase("restartIncomplete.sixdof", bodies, END, DT, write_interval=WRITE, g=(0, 0, -9.81))
    full.run()
    results = []
    for label, damage, damaged in (
        ("sixDoFSim, bodies' state deleted", delete("uniform/sixDoFBodies"), "uniform/sixDoFBodies"),
        ("sixDoFSim, bodies' state cut in half", halve("uniform/sixDoFBodies"), "uniform/sixDoFBodies"),
        ("sixDoFSim, disk full", disk_full, TIME),
    ):
        def make(name, _text, end, dt, write_interval):
            return SixDoFCase(name, bodies, end, dt, write_interval=write_interval, g=(0, 0, -9.81))

        case = damaged_copy(full, "restartIncomplete.sixdofCopy", damage, make=make, text="")
        code, log = run(case, "sixDoFSim")
        results.append(check_refused(label, code, log, damaged))
        case.cleanup()
    full.cleanup()
    return results


def added_mass_checks():
    """(ok, detail) of addedMassRigidBodyMotion restarts from a damaged
    0.02 (writes every step of 0.01)."""
    import tempfile

    work = tempfile.mkdtemp(prefix="restartIncomplete.addedMass.")
    text = added_mass.mesh_dict()
    full = added_mass.make_case(work, "full", text)
    path = os.path.join(full, "system", "controlDict")
    with open(path) as f:
        control = f.read()
    with open(path, "w") as f:
        f.write(control.replace("writeInterval 100;", "writeInterval 1;"))
    code, log = added_mass.run(full)
    results = [(code == 0, f"addedMassRigidBodyMotion: the run to restart from: exit code {code}")]

    def restart(name, damage, dictionary=text):
        case = os.path.join(work, name)
        shutil.copytree(full, case)
        damage(os.path.join(case, "0.02"))
        with open(os.path.join(case, "constant", "dynamicMeshDict"), "w") as f:
            f.write(added_mass.foam_file("dynamicMeshDict", dictionary))
        with open(os.path.join(case, "system", "controlDict")) as f:
            control = f.read()
        with open(os.path.join(case, "system", "controlDict"), "w") as f:
            f.write(control.replace("startFrom startTime;", "startFrom latestTime;")
                    .replace("endTime 0.02;", "endTime 0.03;"))
        return added_mass.run(case)

    state = "uniform/rigidBodyMotionState"
    for label, damage in (("deleted", delete(state)), ("cut in half", halve(state))):
        code, log = restart(label.replace(" ", ""), damage)
        results.append(check_refused(f"addedMassRigidBodyMotion, rigid-body state {label}", code,
                                     log, state, "0.02", "0.01"))

    # With the added-mass coupling (not in test mode) the state must carry
    # the added mass in use; test mode writes none
    coupled = text.replace("test yes;", "test no;")
    code, log = restart("withoutAddedMass", lambda folder: None, coupled)
    ok = code != 0 and "lacks its entry 'addedMass'" in log and "previous complete time" not in log
    results.append((ok, f"addedMassRigidBodyMotion, state without the added mass: exit code {code}"
                    + ("" if ok else "\n" + log[-2500:])))

    code, log = restart("intact", lambda folder: None)
    results.append((code == 0, f"addedMassRigidBodyMotion, intact copy restarts: exit code {code}"
                    + ("" if code == 0 else "\n" + log[-2500:])))
    if os.environ.get("KEEP_CASES") != "1":
        shutil.rmtree(work, ignore_errors=True)
    return results


def main():
    full = ImplicitCase("restartIncomplete", model("implicitNewmark"), END, DT, write_interval=WRITE)
    full.run()
    results = []

    for label, damage, damaged in (
        ("disk full: every file of 0.5 empty", disk_full, TIME),
        ("rigid-body state deleted", delete(STATE), STATE),
        ("rigid-body state empty", empty(STATE), STATE),
        ("rigid-body state cut in half", halve(STATE), STATE),
        ("connector state deleted", delete(CONNECTOR), CONNECTOR),
        ("connector state cut in half", halve(CONNECTOR), CONNECTOR),
        ("implicitNewmark state deleted", delete(SOLVER), SOLVER),
        ("implicitNewmark state cut in half", halve(SOLVER), SOLVER),
        ("uniform/time empty", empty(TIME), TIME),
        ("uniform/time cut in half", halve(TIME), TIME),
        ("what a kill while writing leaves", after_kill, STATE),
    ):
        case = damaged_copy(full, "restartIncomplete.copy", damage)
        code, log = run(case)
        results.append(check_refused(label, code, log, damaged))
        case.cleanup()

    case, code = killed_while_writing("restartIncomplete.killed")
    restart_code, log = run(case)
    ok, detail = check_refused("killed while writing 0.5", restart_code, log, STATE)
    results.append((ok and code == -signal.SIGKILL, f"{detail} (the killed run: exit code {code})"))
    case.cleanup()

    case, code, log = disk_full_for_real("restartIncomplete.diskFull")
    stopped = code != 0 and "cannot write" in log and "0.5/uniform/fmuConnectors/spring" in log
    results.append((stopped, f"disk full while writing: the run stops naming the file (exit code {code})"
                    + ("" if stopped else "\n" + log[-2000:])))
    restart_code, log = run(case)
    results.append(check_refused("restart after the disk was full", restart_code, log, STATE))
    case.cleanup()

    results += sixdof_checks()
    results += added_mass_checks()

    # The intact copy restarts and restores everything
    case = damaged_copy(full, "restartIncomplete.intact", lambda folder: None)
    code, log = run(case)
    restored = code == 0 and "FMU state restored at t = 0.5" in log
    results.append((restored, f"intact copy restarts: exit code {code}"))
    case.cleanup()
    full.cleanup()

    failures = 0
    for ok, detail in results:
        failures += 0 if ok else 1
        print(f"{'PASS' if ok else 'FAIL'} {detail}", flush=True)
    print(f"{len(results) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

"""A restart after the case's restraints changed names each change for what
it is, not as a time written in part.

A run of two bodies tied by a spring FMU and a damper FMU (rigidBodySim)
writes 0.25 and 0.5; copies keep both times, change the case's restraints
and restart from 0.5 (startFrom latestTime):

- the spring renamed: a FatalIOError naming the new name, the connectors
  the time holds (damper, spring), "new since, or one of them renamed" and
  restart fresh; before, it read "not written completely";
- a third connector added: the same error naming it; with 'restart fresh;'
  in it the run goes on, restoring the other two;
- the damper removed: the run goes on, and one warning names the damper's
  state as belonging to no restraint of the case;
- a state file deleted from 0.5 (the time written in part): still the
  FatalIOError of a time not written completely, naming 0.25.

Each state file of 0.5 lists the connectors (entry connectors), which is
what tells the two apart.

sixDoFSim restarts from the copy of the bodies it wrote (0.5/uniform/
sixDoFBodies), so OpenFOAM ignores edits of constant/sixDoFBodies; a body
held by a spring FMU and OpenFOAM's linearSpring restarts after the case's
restraints were edited, and one warning lists every change against the
copy, of any type: a built-in spring added (not applied), the built-in
spring's stiffness changed (both values), and the FMU restraint renamed
(the new name added, the old one removed and still applied). Before, only
the FMU restraint's own entries were compared.
"""
import os
import shutil
import sys

from foamfmi.bridgecase import Case, fmu_path, fmu_restraint, rigid_body, rigid_body_model, spring_fmu, summary
from foamfmi.sixdofcase import SixDoFCase, sixdof_body
from test_sixdof_spring_world import CENTRE, M, J, fmu_spring
from test_restart_incomplete import check_refused, latest_time, run

END, DT, WRITE = 1.0, 0.005, 0.25
BODIES = rigid_body("body1", 2.0, 0.1, (0, 0, 0), "floating") + rigid_body(
    "body2", 3.0, 0.1, (1.2, 0, 0), "floating")


def spring(name="spring", extra=""):
    return spring_fmu(name, "body1", (0, 0, 0), (0, 0, 0), 40, 0, 1.0, body_b="body2", extra=extra)


def damper(name="damper", extra=""):
    return fmu_restraint(name, fmu_path("linearDamper"), "body1",
                         {"damping": 2, "A.p": (0, 0, 0), "B.p": (0, 0, 0)}, body_b="body2",
                         extra=extra)


def copy(full, name, restraints):
    """A copy of the case with 0.25 and 0.5 and the given restraints,
    restarting from the latest time."""
    case = Case(name, rigid_body_model(BODIES, restraints), END, DT, write_interval=WRITE)
    for t in ("0.25", "0.5"):
        shutil.copytree(os.path.join(full.dir, t), os.path.join(case.dir, t))
    latest_time(case)
    return case


def refused_as_new(label, code, log, connector):
    """(ok, detail): the FatalIOError of a restraint new or renamed since
    0.5, and not that of a time written in part."""
    expected = ["FOAM FATAL IO ERROR", f"restraint {connector}: the run starts from t = 0.5",
                "connectors were damper, spring ", "new since, or one of them renamed",
                "restart fresh;"]
    missing = [e for e in expected if e not in log]
    wrong = "not written completely" in log
    ok = code != 0 and not missing and not wrong
    detail = f"{label}: exit code {code}"
    if not ok:
        detail += f", missing {missing}" + (", says 'not written completely'" if wrong else "")
        detail += f":\n{log[-2500:]}"
    return ok, detail


def builtin_spring(name, stiffness):
    return f"""            {name}
            {{
                sixDoFRigidBodyMotionRestraint linearSpring;
                anchor (0 0 2); refAttachmentPt (0 0 0.5);
                stiffness {stiffness}; damping 0; restLength 1.2;
            }}
"""


def sixdof_checks():
    """(ok, detail): sixDoFSim restarts after the case's restraints were
    edited."""
    def bodies(restraints):
        return {"fmu": sixdof_body(M, J, CENTRE, "Newmark", restraints)}

    full = SixDoFCase("restartRestraints.sixdof", bodies(fmu_spring("fmu") + builtin_spring("tie", 300)),
                      END, DT, write_interval=WRITE, g=(0, 0, -9.81))
    full.run()
    case = SixDoFCase("restartRestraints.sixdofEdited",
                      bodies(fmu_spring("fmu").replace("spring_fmu", "tether")
                             + builtin_spring("tie", 350) + builtin_spring("extra", 100)),
                      END, DT, write_interval=WRITE, g=(0, 0, -9.81))
    for t in ("0.25", "0.5"):
        shutil.copytree(os.path.join(full.dir, t), os.path.join(case.dir, t))
    latest_time(case)
    code, log = run(case, "sixDoFSim")
    expected = ["holds the restraints as they were",
                "extra (added): in the case's dictionary, not in the restored copy, so not applied",
                "tether (added)",
                "spring_fmu (removed): in the restored copy, not in the case's dictionary, so still applied",
                "tie.stiffness: 350 in the case's dictionary, 300 in the restored copy"]
    missing = [e for e in expected if e not in log]
    ok = code == 0 and not missing and log.count("holds the restraints as they were") == 1
    case.cleanup()
    full.cleanup()
    return ok, (f"sixDoFSim, restraints edited before a restart: exit code {code}"
                + ("" if ok else f", missing {missing}:\n{log[-3000:]}"))


def main():
    full = Case("restartRestraints", rigid_body_model(BODIES, spring() + damper()), END, DT,
                write_interval=WRITE)
    full.run()
    with open(os.path.join(full.dir, "0.5", "uniform", "fmuConnectors", "spring")) as f:
        listed = "connectors" in f.read()
    results = [(listed, "the state file of 0.5 lists the connectors")]

    case = copy(full, "restartRestraints.renamed", spring("tether") + damper())
    results.append(refused_as_new("spring renamed tether", *run(case), "tether"))
    case.cleanup()

    case = copy(full, "restartRestraints.added", spring() + damper() + damper("extra"))
    results.append(refused_as_new("connector extra added", *run(case), "extra"))
    case.cleanup()

    case = copy(full, "restartRestraints.addedFresh",
                spring() + damper() + damper("extra", "restart fresh;"))
    code, log = run(case)
    restored = log.count("FMU state restored at t = 0.5") == 2
    results.append((code == 0 and restored,
                    f"connector extra added with restart fresh: exit code {code}, "
                    f"{log.count('FMU state restored at t = 0.5')} of 2 states restored"
                    + ("" if code == 0 else f"\n{log[-2000:]}")))
    case.cleanup()

    case = copy(full, "restartRestraints.removed", spring())
    code, log = run(case)
    warned = log.count("holds the states of connectors damper in") == 1 \
        and "no restraint of the case has those names" in log
    results.append((code == 0 and warned,
                    f"damper removed: exit code {code}, one warning naming its state: {warned}"
                    + ("" if code == 0 and warned else f"\n{log[-2500:]}")))
    case.cleanup()

    case = copy(full, "restartRestraints.partial", spring() + damper())
    os.remove(os.path.join(case.dir, "0.5", "uniform", "fmuConnectors", "spring"))
    results.append(check_refused("state of spring deleted (0.5 written in part)", *run(case),
                                 "uniform/fmuConnectors/spring"))
    case.cleanup()
    full.cleanup()

    results.append(sixdof_checks())

    for ok, detail in results:
        print(f"{'PASS' if ok else 'FAIL'} {detail}", flush=True)
    return summary(len(results), sum(1 for ok, _ in results if not ok))


if __name__ == "__main__":
    sys.exit(main())

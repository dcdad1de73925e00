"""What a connector tells the user where the bodies are, and the bodies it
accepts (issue 46: a point taken from the wrong origin, a wrong body name).

1. rigidBodyMotion (rigidBodySim): at its first evaluation the restraint
   logs each body's name and reference point (the origin of the body's
   frame, which its transform sets) and its attachment, A.p and B.p, in
   its frame and in global coordinates; the world is B, at the origin.
   With report on, every report line says its frame and the points of its
   moments.
2. sixDoFRigidBodyMotion (sixDoFSim): the reference point is the centre of
   rotation, which a line constraint sets apart from the centre of mass
   (OpenFOAM's floatingObject: (0.5 0.45 0.1) against (0.5 0.45 0.35)),
   and A.p is taken from it.
3. sixDoF refuses a body entry that names no body of the case, and a
   missing one, with a FatalIOError naming the dictionary's file, the
   restraint, the entry and the valid bodies: a connector to the world
   (its own motion's body), built from the file or from a copy of its
   dictionary (-copyDicts, as a sixDoFRigidBodyMotion solver of
   dynamicMeshDict does), and a connector between two bodies (the case's
   bodies).

The bodies do not move (no gravity, the springs at their rest lengths), so
the first evaluation sees them where they start, to the last digit.
"""
import re
import sys

from foamfmi.bridgecase import Case, fmu_path, fmu_restraint, rigid_body, rigid_body_model, vec
from foamfmi import sixdofcase
from foamfmi.sixdofcase import SixDoFCase, sixdof_body

FRAME = ("(global frame; each moment about its body's reference point, the world's"
         " about the origin)")


def vectors(text):
    """The vectors (x y z) of a line of the log, as float tuples."""
    return [tuple(float(x) for x in v.split()) for v in re.findall(r"\(([-0-9.e ]+)\)", text)]


def body_line(log, head):
    """The vectors of the log's line that starts with head, or None."""
    for line in log.splitlines():
        if line.startswith(head):
            return vectors(line[len(head):])
    return None


def expect(name, log, lines, failures, points=()):
    """lines: text the log holds; points: (head of a line, its vectors)."""
    missing = [line for line in lines if line not in log]
    for head, want in points:
        got = body_line(log, head)
        if got is None or len(got) != len(want) or any(
                abs(g - w) > 1e-12 for gv, wv in zip(got, want) for g, w in zip(gv, wv)):
            missing.append(f"{head} {want} (got {got})")
    if missing:
        start = log.find("first evaluation")
        print(f"FAIL {name}: the log lacks {missing}\n{log[max(start - 200, 0):start + 1200]}")
        failures.append(name)
    else:
        print(f"PASS {name}")


def rigid(failures):
    spring = fmu_restraint("spring", fmu_path("linearSpring"), "hull",
                           "stiffness 10; restLength 1.5; A.p (0.1 0 0); B.p (0.4 0.2 2);",
                           report="on")
    model = rigid_body_model(rigid_body("hull", 2, 0.1, (0.3, 0.2, 0.5), "floating"), spring)
    case = Case("startReport", model, 0.02, 0.01)
    log = case.run()
    expect("rigidBodyMotion: the bodies at the first evaluation", log, [
        "Restraint spring: the bodies at its first evaluation, global coordinates",
        "tension 0 " + FRAME + " force on hull (",
    ], failures, [
        ("    body A hull: reference point", [(0.3, 0.2, 0.5), (0.1, 0, 0), (0.4, 0.2, 0.5)]),
        ("    body B world: reference point", [(0, 0, 0), (0.4, 0.2, 2), (0.4, 0.2, 2)]),
    ])
    case.cleanup()


LINE_CONSTRAINT = """        constraints
        {
            fixedLine
            {
                sixDoFRigidBodyMotionConstraint line;
                centreOfRotation (0.5 0.45 0.1);
                direction (0 1 0);
            }
        }
"""


def sixdof_spring(body, body_b=None, attachment=(0, -0.1, 0.25), rest=0.35):
    return sixdofcase.fmu_restraint(
        "spring", fmu_path("linearSpring"), body,
        f"stiffness 100; restLength {rest}; A.p {vec(attachment)}; B.p (0.5 0 0.35);",
        body_b=body_b, report="on")


def sixdof(failures):
    # The README's sixDoF spring: A.p = refAttachmentPt - centreOfRotation,
    # its anchor 0.35 m from the box's side at rest
    body = sixdof_body(15, 0.1, (0.5, 0.45, 0.35), "Newmark", sixdof_spring("floatingObject"))
    case = SixDoFCase("startReportSixDoF", {"floatingObject": body + LINE_CONSTRAINT}, 0.02, 0.01)
    log = case.run()
    expect("sixDoF: the centre of rotation and A.p from it", log, [
        FRAME + " force on floatingObject (",
    ], failures, [
        ("    body A floatingObject: reference point",
         [(0.5, 0.45, 0.1), (0, -0.1, 0.25), (0.5, 0.35, 0.35)]),
        ("    body B world: reference point", [(0, 0, 0), (0.5, 0, 0.35), (0.5, 0, 0.35)]),
    ])
    case.cleanup()


def refused(failures):
    world = "A connector to the fixed world is in its body's motion, here: "
    cases = {
        "a wrong body": ({"hull": sixdof_body(2, 0.1, (0, 0, 0), "Newmark", sixdof_spring("wrongName"))},
                         (), ["entry body names wrongName, which is not a body of the case",
                              world + "hull\n"]),
        "a wrong body, -copyDicts": (
            {"hull": sixdof_body(2, 0.1, (0, 0, 0), "Newmark", sixdof_spring("wrongName"))},
            ("-copyDicts",), ["entry body names wrongName, which is not a body of the case",
                              world + "hull\n"]),
        "body missing": ({"hull": sixdof_body(2, 0.1, (0, 0, 0), "Newmark",
                                              sixdof_spring("hull").replace("body hull;", ""))},
                         (), ["restraint spring: entry body is missing", world + "hull\n"]),
        "a wrong bodyB": (
            {name: sixdof_body(2, 0.1, centre, "Newmark", sixdof_spring("a", "wrongName"))
             for name, centre in (("a", (0, 0, 0)), ("b", (1, 0, 0)))},
            (), ["entry bodyB names wrongName, which is not a body of the case",
                 "The bodies of the case: a, b\n"]),
    }
    for name, (bodies, args, words) in cases.items():
        case = SixDoFCase("sixDoFBody", bodies, 0.02, 0.01)
        log = case.run(expect_failure=True, args=args)
        words = ["FOAM FATAL IO ERROR", "sixDoFBodies"] + words
        expect(f"sixDoF refuses {name}", log, words, failures)
        case.cleanup()


def main():
    failures = []
    rigid(failures)
    sixdof(failures)
    refused(failures)
    print(f"{len(failures)} failed: {failures}" if failures else "all passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

"""The sixDoF fmuConnector feeds the mass properties a connector declares
(A.m, A.c[1..3], A.J[1..3,1..3], and B's): massEcho.fmu (built here from
massEcho/massEcho.c) returns no load and echoes them as outputs.

1. A body tied to the world, its centre of rotation moved off the centre
   of mass by an axis constraint: A.m is the mass, A.c the centre of mass
   from the centre of rotation in the body frame, A.J the inertia about the
   centre of mass, i.e. the momentOfInertia given (sixDoFRigidBodyMotion
   adds the parallel-axis term about the centre of rotation, the bridge
   takes it off again); B's keep their start values (the world has none).
2. Two bodies: B's are body 2's.
"""
import os
import sys

from foamfmi.bridgecase import summary
from foamfmi.sixdofcase import SixDoFCase, fmu_restraint, sixdof_body, vec

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "massEcho"))
import build  # noqa: E402


def last_row(case):
    out = case.connector("echo")
    return {k: v[-1] for k, v in out.items()}


def main():
    inertia = (0.1, 0.2, 0.3)
    with build.built() as fmu:
        body = sixdof_body(2.5, 0.1, (0, 0, 0.6), restraints=fmu_restraint("echo", fmu, "cube1", None))
        body = body.replace("momentOfInertia (0.1 0.1 0.1)", f"momentOfInertia {vec(inertia)}")
        body += ("        constraints { hinge { sixDoFRigidBodyMotionConstraint point;"
                 " centreOfRotation (0 0 0.8); } }\n")
        world = SixDoFCase("sixdofMass.world", {"cube1": body}, 0.01, 0.001)
        world.run(n_iter=2)

        echo = fmu_restraint("echo", fmu, "cube1", None, "cube2")
        b1 = sixdof_body(2.0, 0.1, (0, 0, 0), restraints=echo)
        b2 = sixdof_body(3.0, 0.4, (1, 0, 0), restraints=echo)
        two = SixDoFCase("sixdofMass.two", {"cube1": b1, "cube2": b2}, 0.01, 0.001)
        two.run(n_iter=2)

    # Sums and differences of a few doubles (the parallel-axis term added
    # by sixDoFRigidBodyMotion and taken off by the bridge): 1e-14
    values = {"A.m": 2.5, "A.c[1]": 0, "A.c[2]": 0, "A.c[3]": -0.2, "B.m": 1}
    for i in range(3):
        for j in range(3):
            values[f"A.J[{i + 1},{j + 1}]"] = inertia[i] if i == j else 0
            values[f"B.J[{i + 1},{j + 1}]"] = 0
    failures = build.check_echo("one body: A's mass properties, B's start values",
                                last_row(world), values, 1e-14)
    world.cleanup()

    values = {"A.m": 2.0, "B.m": 3.0, "B.c[1]": 0, "A.J[1,1]": 0.1, "B.J[1,1]": 0.4,
              "B.J[3,3]": 0.4, "B.J[1,2]": 0}
    failures += build.check_echo("two bodies: A's and B's mass properties", last_row(two), values, 1e-14)
    two.cleanup()
    return summary(2, failures)


if __name__ == "__main__":
    sys.exit(main())

"""The bodies' placement read back from a written time (foamfmi.bodystate,
what renderScene places connectors by when a case has no table of the
bodies' motion) against OpenFOAM's own.

A rigidBodyMotion model with a body on every kind of joint OpenFOAM has
(floating; composite Px + Ry under a parent; Rs, the unit quaternion; Ra
about a skew axis; the Euler joints Rxyz, Rzyx, Ryxz; Pa; composite Pxyz +
Rz; a body merged into another), each placed by a rotated and shifted
`transform`, spinning and sliding from given joint velocities under tilted
gravity, is run by rigidBodySim for 0.5 s. At each written time, the poses
that bodystate.written_poses computes from <time>/uniform/rigidBodyMotionState
(q) and constant/dynamicMeshDict (as foamDictionary -expand -precision 17
prints it) give
each body's centre of mass and rotation; rigidBodySim's bodies.dat holds the
same from OpenFOAM's model (X0 of each body). They agree to 1e-9 m and 1e-9:
both are the same double-precision arithmetic on q written with 17 digits,
so only the order of a few sums differs (measured: below 1e-15). The merged
body has no row of its own in bodies.dat: its pose must be its master's
with its transform, to the same tolerance; its mass moves the arm's centre
of mass in bodies.dat, which the arm's check takes into account.
"""
import math
import os
import sys

from foamfmi import bodystate, foamdict
from foamfmi.bridgecase import Case, check, rigid_body_model, summary, vec

TOLERANCE = 1e-9

# (name, parent, joint, transform rotation about z in degrees, origin,
#  centre of mass in the body frame)
BODIES = (
    ("floater", "root", "{ type floating; }", 30, (0.5, 0.2, 0.1), (0.05, -0.02, 0.01)),
    ("arm", "floater", "{ type composite; joints ({ type Px; } { type Ry; }); }", -20,
     (0.1, 0, 0.3), (0.1, 0, 0)),
    ("ball", "root", "{ type Rs; }", 45, (-1, 0, 0), (0, 0.1, 0.2)),
    ("skew", "root", "{ type Ra; axis (1 1 0.5); }", 10, (0, 1, 0), (0.2, 0, 0)),
    ("xyz", "root", "{ type Rxyz; }", 0, (1, 1, 0), (0.1, 0.1, 0)),
    ("zyx", "root", "{ type Rzyx; }", 60, (1, -1, 0), (0, 0.1, 0.1)),
    ("yxz", "root", "{ type Ryxz; }", -45, (-1, -1, 0), (0.1, 0, 0.1)),
    ("slider", "root", "{ type Pa; axis (1 0 1); }", 15, (2, 0, 0), (0, 0, 0.1)),
    ("cart", "root", "{ type composite; joints ({ type Pxyz; } { type Rz; }); }", 90,
     (0, 2, 0), (0.1, 0.1, 0.1)),
)
# Joint velocities, in the order of the bodies' coordinates above
QDOT = (0.1, -0.2, 0.3, 0.8, -1.2, 0.5,     # floater: Pxyz, Rzyx
        0.2, 1.5,                           # arm: Px, Ry
        0.6, -0.4, 0.9,                     # ball: Rs
        2.0,                                # skew
        0.7, -0.3, 1.1,                     # xyz
        -0.9, 0.4, 0.6,                     # zyx
        0.3, 1.2, -0.8,                     # yxz
        0.5,                                # slider
        0.1, 0.2, -0.1, 1.7)                # cart: Pxyz, Rz


def transform(degrees, origin):
    """OpenFOAM's transform (E r): E the rotation about z as global to body."""
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    return "(%r %r 0 %r %r 0 0 0 1) %s" % (c, s, -s, c, vec(origin))


def body(name, parent, joint, degrees, origin, com):
    return (f"    {name}\n    {{\n        type rigidBody;\n        parent {parent};\n"
            f"        mass 1;\n        centreOfMass {vec(com)};\n"
            f"        inertia (0.02 0 0 0.03 0 0.04);\n"
            f"        transform {transform(degrees, origin)};\n"
            f"        joint {joint}\n    }}\n")


LID_ORIGIN = (0.05, 0.02, 0.1)
MERGED = ("lid    { type cuboid; mass 0.1; L (0.1 0.1 0.02); centreOfMass (0 0 0);"
          " mergeWith arm; transform %s; }\n" % transform(25, LID_ORIGIN))


def main():
    model = rigid_body_model(
        "".join(body(*b) for b in BODIES) + MERGED, "", g=(1.0, -0.5, -9.81),
        extra="    qDot %d (%s);\n" % (len(QDOT), " ".join(repr(v) for v in QDOT)))
    case = Case("written_poses", model, end_time=0.5, delta_t=0.001, write_interval=0.25)
    failures = checks = 0
    try:
        case.run()
        table = case.bodies()
        tree = foamdict.expanded(case.dir, "constant/dynamicMeshDict", precision=17)
        coms = {name: com for name, _, _, _, _, com in BODIES}
        # The lid's mass (0.1 kg at its frame's origin) merged into the
        # arm's (1 kg) moves the arm's centre of mass, which bodies.dat gives
        coms["arm"] = tuple((1.0 * a + 0.1 * b) / 1.1
                            for a, b in zip(coms["arm"], LID_ORIGIN))
        for time in ("0.25", "0.5"):
            poses = bodystate.written_poses(case.dir, time, tree)
            row = min(range(len(table["Time"])),
                      key=lambda i: abs(table["Time"][i] - float(time)))
            worst_c = worst_r = 0.0
            for name, com in coms.items():
                origin, R = poses[name]
                centre = [origin[i] + sum(R[i][j] * com[j] for j in range(3)) for i in range(3)]
                worst_c = max(worst_c, max(abs(centre[i] - table[f"{name}.c.{x}"][row])
                                           for i, x in enumerate("xyz")))
                worst_r = max(worst_r, max(abs(R[i][j] - table[f"{name}.R.{a}{b}"][row])
                                           for i, a in enumerate("xyz")
                                           for j, b in enumerate("xyz")))
            checks += 1
            failures += check(f"t = {time}: {len(coms)} bodies placed as OpenFOAM does",
                              worst_c < TOLERANCE and worst_r < TOLERANCE,
                              f"centres of mass within {worst_c:.2g} m, rotations within "
                              f"{worst_r:.2g} (limit {TOLERANCE:g})")
            # The merged body: its master's pose and its transform
            (o_arm, r_arm), (o_lid, r_lid) = poses["arm"], poses["lid"]
            a = math.radians(25)
            r_local = ((math.cos(a), -math.sin(a), 0), (math.sin(a), math.cos(a), 0), (0, 0, 1))
            expected_r = [[sum(r_arm[i][k] * r_local[k][j] for k in range(3)) for j in range(3)]
                          for i in range(3)]
            expected_o = [o_arm[i] + sum(r_arm[i][k] * LID_ORIGIN[k] for k in range(3))
                          for i in range(3)]
            gap = max(max(abs(o_lid[i] - expected_o[i]) for i in range(3)),
                      max(abs(r_lid[i][j] - expected_r[i][j]) for i in range(3)
                          for j in range(3)))
            checks += 1
            failures += check(f"t = {time}: the merged body on its master",
                              gap < TOLERANCE, f"within {gap:.2g} (limit {TOLERANCE:g})")
        # The bodies moved: a comparison of bodies at rest would prove little
        moved = max(abs(table["floater.c.z"][-1] - table["floater.c.z"][0]),
                    abs(table["ball.R.xx"][-1] - table["ball.R.xx"][0]))
        checks += 1
        failures += check("the bodies moved", moved > 0.1, f"by {moved:.3g}")
    finally:
        case.cleanup()
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())

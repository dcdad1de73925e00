"""The morphing weight of the added-mass motion solvers with a distance
scale (distanceScale (sx sy sz): the distance to the body's patches with
each coordinate multiplied by its factor), against the analytic weight.

A flume of 3 x 1 m with a box of 0.5 x 0.2 m cut out of it (x 1.25-1.75 m,
z 0.4-0.6 m; 24 x 10 cells, one across y), the box's faces the body's
patch. The body falls under gravity for two time steps (test mode: no fluid
loads), a pure translation D, moved by moveDynamicMesh with
addedMassRigidBodyMotion (joint Pz) and addedMassSixDoFRigidBodyMotion (a
heave constraint). Every mesh point must then have moved by w(d) D, d the
scaled distance to the box (to an axis-aligned rectangle: analytic), w the
half-cosine weight of OpenFOAM's solvers between innerDistance 0.05 and
outerDistance 1.2. With distanceScale (1 1 4) the bed, 0.4 m below the
keel (1.6 scaled), stays where it is while points 1 m ahead of the box
along the flume move; without it (the default) the bed under the box moves
and the far points do not, as before.

On 2 ranks, the second holding the flume's top right corner (x > 1.75 m,
z > 0.6 m) and none of the box's faces, its points (nearest to the box's
corner, within the outer distance) moved by the faces the first holds,
every point moves as in serial, against the same weight.

A scale with a component not above zero stops the solver when it is built,
with a FatalIOError naming distanceScale and what it expects, under both
solvers.
"""
import math
import os
import subprocess
import sys

import test_added_mass_entries as entries
from foamfmi.bridgecase import foam_file
from foamfmi.dictionary import read_points
from test_added_mass_entries import refused, run, run_checks

BOX = (1.25, 1.75, 0.4, 0.6)  # x0, x1, z0, z1 [m]
INNER, OUTER = 0.05, 1.2

# 3 x 3 blocks around the box (the centre one left out); x 10, 4, 10 cells,
# z 4, 2, 4
BLOCK_MESH = """
vertices
(
    (0 0 0) (1.25 0 0) (1.75 0 0) (3 0 0)
    (0 0 0.4) (1.25 0 0.4) (1.75 0 0.4) (3 0 0.4)
    (0 0 0.6) (1.25 0 0.6) (1.75 0 0.6) (3 0 0.6)
    (0 0 1) (1.25 0 1) (1.75 0 1) (3 0 1)
    (0 0.1 0) (1.25 0.1 0) (1.75 0.1 0) (3 0.1 0)
    (0 0.1 0.4) (1.25 0.1 0.4) (1.75 0.1 0.4) (3 0.1 0.4)
    (0 0.1 0.6) (1.25 0.1 0.6) (1.75 0.1 0.6) (3 0.1 0.6)
    (0 0.1 1) (1.25 0.1 1) (1.75 0.1 1) (3 0.1 1)
);
blocks
(
%s
);
boundary
(
    box
    {
        type wall;
        faces ((5 6 22 21) (9 25 26 10) (5 21 25 9) (6 10 26 22));
    }
    walls
    {
        type wall;
        faces
        (
%s
        );
    }
    frontAndBack
    {
        type empty;
        faces
        (
%s
        );
    }
);
"""

# test_added_mass_entries' two steps, the points written at the end to 15
# digits
CONTROL = entries.CONTROL.replace("writeInterval 100;", "writeInterval 2;").replace(
    "writePrecision 12;", "writePrecision 15;")

POINT_DISPLACEMENT = """
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    box { type calculated; value uniform (0 0 0); }
    // the flume's walls take the weight's motion as every other point: the
    // test is of the weight, not of a case that could run
    walls { type calculated; value uniform (0 0 0); }
    frontAndBack { type empty; }
}
"""


def block_mesh():
    """blockMeshDict's blocks, the flume's walls and its front and back
    (empty) around the box."""
    nx, nz = (10, 4, 10), (4, 2, 4)
    blocks, walls, sides = [], [], []
    for k in range(3):
        for i in range(3):
            if (i, k) == (1, 1):
                continue
            a = 4 * k + i
            b, c, d = a + 1, a + 5, a + 4
            blocks.append(f"    hex ({a} {b} {b + 16} {a + 16} {d} {c} {c + 16} {d + 16}) "
                          f"({nx[i]} 1 {nz[k]}) simpleGrading (1 1 1)")
            # front (y = 0) and back (y = 0.1) of every block
            sides.append(f"            ({a} {d} {c} {b})")
            sides.append(f"            ({a + 16} {b + 16} {c + 16} {d + 16})")
            if k == 0:
                walls.append(f"            ({a} {b} {b + 16} {a + 16})")
            if k == 2:
                walls.append(f"            ({d} {d + 16} {c + 16} {c})")
            if i == 0:
                walls.append(f"            ({a} {a + 16} {d + 16} {d})")
            if i == 2:
                walls.append(f"            ({b} {c} {c + 16} {b + 16})")
    return BLOCK_MESH % ("\n".join(blocks), "\n".join(walls), "\n".join(sides))


def rigid_body_dict(scale):
    """test_added_mass_entries' dynamicMeshDict for this flume's box, with
    the distances of this test and the scale entry given."""
    text = entries.mesh_dict()
    for old, new in (("(0.5 0.5 0)", "(1.5 0.05 0.5)"), ("patches (body);", "patches (box);"),
                     ("innerDistance 0.1;", f"innerDistance {INNER};"),
                     ("outerDistance 0.6;", f"outerDistance {OUTER}; {scale}")):
        if old not in text:
            raise RuntimeError(f"test_added_mass_entries.mesh_dict: no '{old}'")
        text = text.replace(old, new)
    return text


def six_dof_dict(scale):
    return f"""
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs (sixDoFRigidBodyMotion foamFmiRigidBodyCoupling);
motionSolver addedMassSixDoFRigidBodyMotion;
addedMassSixDoFRigidBodyMotionCoeffs
{{
    test yes;
    rho rhoInf;
    rhoInf 1000;
    g (0 0 -9.81);
    patches (box);
    innerDistance {INNER};
    outerDistance {OUTER};
    {scale}
    mass 1;
    centreOfMass (1.5 0.05 0.5);
    momentOfInertia (0.1 0.1 0.1);
    report off;
    solver {{ type Newmark; }}
    constraints
    {{
        heave {{ sixDoFRigidBodyMotionConstraint line; direction (0 0 1); }}
        level {{ sixDoFRigidBodyMotionConstraint orientation; }}
    }}
    coupling {{ addedMass on; }}
}}
"""


def make_case(work, name, dynamic_mesh_dict):
    """The flume in work/name, meshed, with the given dynamicMeshDict."""
    return entries.make_case(work, name, dynamic_mesh_dict, POINT_DISPLACEMENT,
                             control=CONTROL, block_mesh=block_mesh())


def run_parallel(case):
    """moveDynamicMesh on 2 ranks, the second the last block's cells (the
    top right corner, 10 x 4 cells, blockMesh's last): (exit code, log)."""
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write(foam_file("decomposeParDict", "numberOfSubdomains 2;\nmethod manual;\n"
                          "coeffs { dataFile \"cellDecomposition\"; }\n"))
    cells = 10 * 4 + 4 * 4 + 10 * 4 + 10 * 2 + 10 * 2 + 10 * 4 + 4 * 4 + 10 * 4
    with open(os.path.join(case, "constant", "cellDecomposition"), "w") as f:
        f.write(foam_file("cellDecomposition", "%d\n(\n%s\n)\n" % (
            cells, "\n".join(["0"] * (cells - 40) + ["1"] * 40))).replace(
                "class dictionary", "class labelList"))
    env = dict(os.environ)
    if os.getuid() == 0:  # mpirun refuses root without these
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    log = ""
    for command in (["decomposePar", "-case", case],
                    ["mpirun", "-np", "2", "moveDynamicMesh", "-case", case, "-parallel"]):
        result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True, env=env)
        log += result.stdout
        if result.returncode != 0:
            return result.returncode, log
    return 0, log


def moved_points(folders):
    """(initial, moved) points of the mesh in each folder."""
    pairs = []
    for folder in folders:
        pairs.append((read_points(os.path.join(folder, "constant", "polyMesh", "points")),
                      read_points(os.path.join(folder, "0.02", "polyMesh", "points"))))
    return pairs


def weight(point, scale):
    """OpenFOAM's half-cosine weight of the scaled distance to the box."""
    x, _, z = point
    dx = max(BOX[0] - x, x - BOX[1], 0.0) * scale[0]
    dz = max(BOX[2] - z, z - BOX[3], 0.0) * scale[2]
    u = min(max((OUTER - math.hypot(dx, dz)) / (OUTER - INNER), 0.0), 1.0)
    return 0.5 - 0.5 * math.cos(u * math.pi)


def motion_checks(work, solver, make_dict):
    """(name, ok, detail) of the moved points against w(d) D, with and
    without the scale."""
    results = []
    for label, scale, entry, ranks in (("scaled", (1, 1, 4), "distanceScale (1 1 4);", 1),
                                       ("default", (1, 1, 1), "", 1),
                                       ("scaledParallel", (1, 1, 4), "distanceScale (1 1 4);", 2)):
        name = f"{solver}.{label}"
        case = make_case(work, name, make_dict(entry))
        code, log = run(case) if ranks == 1 else run_parallel(case)
        if code != 0:
            results.append((name, False, f"exit code {code}\n{log[-2500:]}"))
            continue
        pairs = moved_points([case] if ranks == 1 else
                             [os.path.join(case, "processor%d" % i) for i in range(ranks)])
        # The body's displacement: that of a point of the box's patch
        fall = next(q[2] - p[2] for before, after in pairs
                    for p, q in zip(before, after) if p == (1.25, 0.0, 0.4))
        worst, moved_far, moved_bed = 0.0, 0.0, 0.0
        for p, q in ((p, q) for before, after in pairs for p, q in zip(before, after)):
            expected = (p[0], p[1], p[2] + weight(p, scale) * fall)
            worst = max(worst, max(abs(a - b) for a, b in zip(q, expected)))
            if abs(p[0] - 0.25) < 1e-9 and abs(p[2] - 0.5) < 0.11:
                moved_far = max(moved_far, abs(q[2] - p[2]))
            if p[2] == 0.0 and BOX[0] <= p[0] <= BOX[1]:
                moved_bed = max(moved_bed, abs(q[2] - p[2]))
        # 1e-9 of the fall: the points are written to 15 digits, the weight's
        # arithmetic is the same as the formula's to round-off
        ok = fall < -1e-4 and worst <= 1e-9 * abs(fall)
        if scale[2] != 1:
            # 1 m ahead of the box (scaled 1.0 < OUTER) it moves; the bed
            # (0.4 m below the keel, 1.6 scaled) does not
            ok = ok and moved_far > 0.001 * abs(fall) and moved_bed == 0.0
        else:
            # unscaled, the bed (0.4 < OUTER) moves and the far points
            # (1 m away) hardly: w(1.0) = 0.067
            ok = ok and moved_bed > 0.1 * abs(fall)
        results.append((name, ok,
                        f"fall {fall:.6g} m, largest difference from w(d) D {worst:.3g} m, "
                        f"far point moved {moved_far:.3g} m, bed {moved_bed:.3g} m"))
    return results


def checks(work):
    expected = ["distanceScale", "each > 0"]
    results = motion_checks(work, "rigidBody", rigid_body_dict)
    results += motion_checks(work, "sixDoF", six_dof_dict)
    for solver, make_dict in (("rigidBody", rigid_body_dict), ("sixDoF", six_dof_dict)):
        for label, entry in (("zero", "distanceScale (1 0 4);"),
                             ("negative", "distanceScale (1 1 -4);")):
            name = f"{solver}.{label}Scale"
            code, log = run(make_case(work, name, make_dict(entry)))
            results.append((name, *refused(code, log, expected)))
    return results


if __name__ == "__main__":
    sys.exit(run_checks("morphingDistance.", checks))

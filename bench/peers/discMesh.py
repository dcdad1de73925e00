"""FloatStepper's disc in reduced gravity (run/discInGravity) meshed
without the v2312 utilities its scripts call (mirrorMesh, autoPatch,
createPatch, surfaceMeshExtract, surfaceOrient are not built here): its
quadrant's mesh parameters, the four mirrored quadrants as four blocks of
one blockMeshDict, and the disc's surface (floater.stl) from the mesh's
patch. For bench/peers/lightBodyCompare."""

import math
import os
import re

from lightRuns import fail


def mesh_parameters(case):
    """R1, R2, z1, z2 and grading of the case's writeMeshParmFile.py."""
    with open(os.path.join(case, "writeMeshParmFile.py")) as f:
        text = f.read()
    values = {}
    for name in ("R1", "R2", "z1", "z2", "grading"):
        m = re.search(r"^%s\s*=\s*(\S+)" % name, text, re.M)
        if not m:
            fail("%s/writeMeshParmFile.py: no %s" % (case, name))
        values[name] = float(m.group(1))
    return values


def block_mesh_dict(p, nx, ny):
    """The case's mesh (blockMesh of one quadrant, mirrored about x and y,
    patches floatingObject, rim, front and back) as four blocks."""
    angles = (0, 90, 180, 270)

    def index(level, ring, i):            # level z1/z2, ring R1/R2, angle
        return 8 * level + 4 * ring + i % 4

    lines = ["FoamFile", "{", "    version     2.0;", "    format      ascii;",
             "    class       dictionary;", "    object      blockMeshDict;", "}", "",
             "// FloatStepper's run/discInGravity mesh (writeMeshParmFile.py, blockMeshDict,",
             "// mirrorMesh about x and y, autoPatch, createPatch) as four blocks:",
             "// bench/peers/lightBodyCompare", "", "vertices", "("]
    for z in (p["z1"], p["z2"]):
        for radius in (p["R1"], p["R2"]):
            for a in angles:
                lines.append("    (%.12g %.12g %.12g)" % (radius * math.cos(math.radians(a)),
                                                          radius * math.sin(math.radians(a)), z))
    lines += [");", "", "blocks", "("]
    for i in range(4):
        vertices = [index(0, 0, i), index(0, 1, i), index(0, 1, i + 1), index(0, 0, i + 1),
                    index(1, 0, i), index(1, 1, i), index(1, 1, i + 1), index(1, 0, i + 1)]
        lines.append("    hex (%s) (%d %d 1) simpleGrading (%.12g 1 1)"
                     % (" ".join(str(v) for v in vertices), nx, ny, p["grading"]))
    lines += [");", "", "edges", "("]
    for level, z in enumerate((p["z1"], p["z2"])):
        for ring, radius in enumerate((p["R1"], p["R2"])):
            for i, a in enumerate(angles):
                mid = math.radians(a + 45)
                lines.append("    arc %d %d (%.12g %.12g %.12g)"
                             % (index(level, ring, i), index(level, ring, i + 1),
                                radius * math.cos(mid), radius * math.sin(mid), z))
    lines += [");", "", "boundary", "("]
    patches = (("floatingObject", "patch",
                [(index(0, 0, i), index(0, 0, i + 1), index(1, 0, i + 1), index(1, 0, i))
                 for i in range(4)]),
               ("rim", "patch",
                [(index(0, 1, i), index(0, 1, i + 1), index(1, 1, i + 1), index(1, 1, i))
                 for i in range(4)]),
               ("front", "empty",
                [(index(1, 0, i), index(1, 1, i), index(1, 1, i + 1), index(1, 0, i + 1))
                 for i in range(4)]),
               ("back", "empty",
                [(index(0, 0, i), index(0, 1, i), index(0, 1, i + 1), index(0, 0, i + 1))
                 for i in range(4)]))
    for name, kind, faces in patches:
        lines += ["    %s" % name, "    {", "        type %s;" % kind, "        faces", "        ("]
        lines += ["            (%d %d %d %d)" % f for f in faces]
        lines += ["        );", "    }"]
    lines += [");", "", "mergePatchPairs", "(", ");", ""]
    return "\n".join(lines)


def foam_list(path):
    """The entries of an ascii OpenFOAM list file (points, faces), as text."""
    with open(path) as f:
        text = f.read()
    m = re.search(r"^\s*(\d+)\s*\n\s*\(", text, re.M)
    if not m:
        fail("%s: not an ascii list" % path)
    return text[m.end():]


def write_disc_stl(case, patch, path):
    """The patch's faces as an ascii STL, triangles facing out of the disc
    (the surfaceMeshExtract -patches and surfaceOrient -inside of the case's
    Allrun): the disc's side, which floaterInertia's divergence-theorem
    integrals of x n_x and y n_y need (the end faces have n_x = n_y = 0)."""
    mesh = os.path.join(case, "constant", "polyMesh")
    points = [tuple(float(x) for x in p.split()) for p in
              re.findall(r"^\(([^()]*)\)\s*$", foam_list(os.path.join(mesh, "points")), re.M)]
    faces = [[int(i) for i in f.split()] for f in
             re.findall(r"^\d+\(([^()]*)\)\s*$", foam_list(os.path.join(mesh, "faces")), re.M)]
    with open(os.path.join(mesh, "boundary")) as f:
        m = re.search(r"\b%s\s*\{([^}]*)\}" % patch, f.read())
    if not m:
        fail("%s/boundary: no patch %s" % (mesh, patch))
    n = int(re.search(r"nFaces\s+(\d+);", m.group(1)).group(1))
    start = int(re.search(r"startFace\s+(\d+);", m.group(1)).group(1))
    lines = ["solid %s" % patch]
    for face in faces[start:start + n]:
        p = [points[i] for i in face]
        for a, b, c in ((p[0], p[k], p[k + 1]) for k in range(1, len(p) - 1)):
            u = [b[k] - a[k] for k in range(3)]
            v = [c[k] - a[k] for k in range(3)]
            normal = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                      u[0] * v[1] - u[1] * v[0]]
            centre = [(a[k] + b[k] + c[k]) / 3 for k in range(3)]
            if normal[0] * centre[0] + normal[1] * centre[1] < 0:
                b, c = c, b
                normal = [-x for x in normal]
            lines += ["facet normal %.12g %.12g %.12g" % tuple(normal), " outer loop"]
            lines += ["  vertex %.12g %.12g %.12g" % q for q in (a, b, c)]
            lines += [" endloop", "endfacet"]
    lines.append("endsolid %s" % patch)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")

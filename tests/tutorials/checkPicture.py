"""Picture checks: pvpython checkPicture.py -- CHECK ARGS (see each check)."""
import json
import math
import os
import sys

import numpy as np
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def read_png(path):
    """RGB pixels, rows from the top."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    if w*h <= 1:
        fail("%s: not a PNG picture" % path)
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[::-1, :, :3].astype(int)


class Camera:
    """The pinhole (or parallel) camera of renderScene's 'camera:' line."""

    def __init__(self, path):
        words = open(path).read().split()
        get = lambda key, n: [float(v) for v in
                              words[words.index(key) + 1:words.index(key) + 1 + n]]
        self.position = np.array(get("position", 3))
        focal = np.array(get("focalPoint", 3))
        up = np.array(get("viewUp", 3))
        self.angle = get("viewAngle", 1)[0]
        self.parallel = get("parallelProjection", 1)[0] == 1
        self.scale = get("parallelScale", 1)[0]
        self.size = [int(v) for v in get("size", 2)]
        self.d = (focal - self.position)/np.linalg.norm(focal - self.position)
        self.r = np.cross(self.d, up)
        self.r /= np.linalg.norm(self.r)
        self.u = np.cross(self.r, self.d)

    def project(self, points):
        """Pixel (column, row from the top) of each world point."""
        v = np.atleast_2d(points) - self.position
        x, y, z = v @ self.r, v @ self.u, v @ self.d
        w, h = self.size
        if self.parallel:
            half = self.scale
            sx, sy = x/half, y/half
        else:
            t = math.tan(math.radians(self.angle)/2)
            sx, sy = x/z/t, y/z/t
        return np.column_stack([w/2 + sx*h/2, h/2 - sy*h/2])


def box_corners(lo, hi):
    return np.array([[(lo, hi)[i >> k & 1][k] for k in range(3)]
                     for i in range(8)])


def polygon_mask(shape, polygon):
    """Pixels whose centre is inside the convex polygon (any vertex order)."""
    polygon = np.asarray(polygon)
    centre = polygon.mean(axis=0)
    order = np.argsort(np.arctan2(polygon[:, 1] - centre[1],
                                  polygon[:, 0] - centre[0]))
    polygon = polygon[order]
    rows, cols = np.mgrid[0:shape[0], 0:shape[1]]
    px, py = cols + 0.5, rows + 0.5
    inside = np.ones(shape, bool)
    for a, b in zip(polygon, np.roll(polygon, -1, axis=0)):
        cross = (b[0] - a[0])*(py - a[1]) - (b[1] - a[1])*(px - a[0])
        inside &= cross >= 0
    return inside


def hull(points):
    """Convex hull of 2D points (monotone chain)."""
    pts = sorted(map(tuple, points))
    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0])*(p[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1])*(p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out
    lower, upper = half(pts), half(reversed(pts))
    return np.array(lower[:-1] + upper[:-1])


def grow(mask, n):
    """The mask grown by n pixels (square neighbourhood)."""
    out = mask.copy()
    for _ in range(n):
        g = out.copy()
        g[1:, :] |= out[:-1, :]
        g[:-1, :] |= out[1:, :]
        g[:, 1:] |= out[:, :-1]
        g[:, :-1] |= out[:, 1:]
        out = g
    return out


def water(p):
    return (p[..., 2] > p[..., 0] + 40) & (p[..., 2] > p[..., 1] + 10)


def body(p):
    return ((p[..., 0] > 150) & (p[..., 0] > p[..., 1] + 60)
            & (p[..., 1] > p[..., 2] + 20))


def differ(a, b):
    return np.abs(a - b).max(axis=2) > 30


def located(name, mask, region, margin, least):
    """mask lies in region (grown by margin pixels) and has least pixels."""
    n = int(mask.sum())
    outside = int((mask & ~grow(region, margin)).sum())
    if n < least:
        fail("%s: %d pixels, expected at least %d" % (name, n, least))
    if outside > 0.02*n:
        fail("%s: %d of %d pixels outside the projected region"
             % (name, outside, n))
    print("ok: %s: %d pixels, %d outside the projection (+%d px)"
          % (name, n, outside, margin))


def cube_box(centre, lo, hi):
    return box_corners([c + l for c, l in zip(centre, lo)],
                       [c + h for c, h in zip(centre, hi)])


def body_centre(dat, time):
    """The centre of rotation at `time` in a rigidBodyMotion .dat file."""
    rows = [list(map(float, l.split())) for l in open(dat)
            if l.strip() and not l.startswith("#")]
    row = min(rows, key=lambda r: abs(r[0] - time))
    return row[1:4]


def check_3d(png, nobody, nolines, fromdat, case, time, width, height):
    """The moored cube: size, water, body, lines, both line sources."""
    cam = Camera(png + ".camera")
    p = read_png(png)
    if p.shape[:2] != (height, width):
        fail("%s: %dx%d pixels, asked for %dx%d"
             % (png, p.shape[1], p.shape[0], width, height))
    print("ok: size %dx%d" % (width, height))

    # Free surface: the still-water plane across the tank (-1 0 0)-(1 1 1)
    surface = cam.project([[-1, 0, 0.5], [1, 0, 0.5], [1, 1, 0.5], [-1, 1, 0.5]])
    region = polygon_mask(p.shape[:2], surface)
    wet = water(p)
    fraction = wet.sum()/region.sum()
    if not 0.85 < fraction < 1.1:
        fail("water colour on %.2f of the projected free surface's area"
             % fraction)
    print("ok: water colour on %.2f of the projected free surface" % fraction)
    # Within the heights of the surface: still water and the dam-break
    # column (0.6 m high for x > 0.9 m at the start), as the cube moves it
    band = polygon_mask(p.shape[:2], hull(cam.project(
        box_corners([-1, 0, 0.45], [1, 1, 0.65]))))
    located("water colour", wet, band, 3, 0.5*region.sum())

    # The cube: 0.2 m, its centre of mass 0.03 m above its bottom face
    centre = body_centre(os.path.join(case, "postProcessing/rigidBodyMotion/floatingObject.dat"), time)
    cube = hull(cam.project(cube_box(centre, [-0.1, -0.1, -0.03], [0.1, 0.1, 0.17])))
    square = polygon_mask(p.shape[:2], cube)
    located("body colour", body(p), square, 3, 0.25*square.sum())
    located("body (with against without)", differ(p, read_png(nobody)),
            square, 3, 0.5*square.sum())

    # The lines: pixels that differ without them lie along their projections
    near = np.zeros(p.shape[:2], bool)
    length = 0.0
    folder = os.path.join(case, "VTK/fmuConnectors")
    for series in sorted(f for f in os.listdir(folder) if f.endswith(".series")):
        files = json.load(open(os.path.join(folder, series)))["files"]
        name = [f["name"] for f in files if abs(f["time"] - time) < 1e-9][0]
        lines = open(os.path.join(folder, name)).read().split("\n")
        n = int([l for l in lines if l.startswith("POINTS")][0].split()[1])
        start = [i for i, l in enumerate(lines) if l.startswith("POINTS")][0] + 1
        xyz = np.array(" ".join(lines[start:start + n]).split(), float).reshape(n, 3)
        pix = cam.project(xyz)
        for a, b in zip(pix, pix[1:]):
            steps = int(np.linalg.norm(b - a)) + 1
            length += steps
            for s in np.linspace(0, 1, steps + 1):
                c, r = (a + s*(b - a)).astype(int)
                if 0 <= r < p.shape[0] and 0 <= c < p.shape[1]:
                    near[r, c] = True
    located("lines (with against without)", differ(p, read_png(nolines)),
            near, 6, 1.5*length)

    same = differ(p, read_png(fromdat)).sum()
    if same > 1e-4*p.shape[0]*p.shape[1]:
        fail("the picture from the .dat files differs from the one from the"
             " VTK files in %d pixels" % same)
    print("ok: the same picture from the .dat files (%d pixels differ)" % same)


def check_2d(png, nobody, case, time):
    """The overset cube, side view: water below z = 0.5 m, the body."""
    cam = Camera(png + ".camera")
    p = read_png(png)
    if [p.shape[1], p.shape[0]] != cam.size or cam.size[0] != 1280:
        fail("%s: %dx%d pixels, expected 1280 wide and the size reported %s"
             % (png, p.shape[1], p.shape[0], cam.size))
    print("ok: size %dx%d" % tuple(cam.size))
    below = polygon_mask(p.shape[:2], cam.project(
        [[-1.6, 0, 0.0], [1.6, 0, 0.0], [1.6, 0, 0.47], [-1.6, 0, 0.47]]))
    above = polygon_mask(p.shape[:2], cam.project(
        [[-1.6, 0, 0.53], [1.6, 0, 0.53], [1.6, 0, 1.0], [-1.6, 0, 1.0]]))
    wet = water(p)
    filled = wet[below].mean()
    if filled < 0.9:
        fail("water colour on %.2f of the tank below the surface" % filled)
    if wet[above].mean() > 0.01:
        fail("water colour on %.3f of the tank above the surface"
             % wet[above].mean())
    print("ok: water colour on %.3f of the tank below z = 0.47 m, %.4f above"
          " z = 0.53 m" % (filled, wet[above].mean()))
    centre = body_centre(os.path.join(case, "postProcessing/rigidBodyMotion/floatingObject.dat"), time)
    square = polygon_mask(p.shape[:2], cam.project(
        cube_box(centre, [-0.1, 0, -0.03], [0.1, 0, 0.17])[[0, 1, 5, 4]]))
    located("body colour", body(p), square, 3, 0.6*square.sum())
    located("body (with against without)", differ(p, read_png(nobody)),
            square, 3, 0.6*square.sum())


def rotation(vector_deg):
    """Rotation matrix of a rotation vector in degrees (Rodrigues)."""
    w = np.radians(np.asarray(vector_deg, float))
    angle = np.linalg.norm(w)
    if angle < 1e-15:
        return np.eye(3)
    k = w/angle
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle)*K + (1 - math.cos(angle))*K @ K


def body_pose(case, body, time):
    """Origin and rotation of a body at `time` from its logged motion."""
    rows = [list(map(float, l.split())) for l in open(os.path.join(
        case, "postProcessing/rigidBodyMotion/%s.dat" % body))
            if l.strip() and not l.startswith("#")]
    row = min(rows, key=lambda r: abs(r[0] - time))
    return np.array(row[1:4]), rotation(row[5:8])


def dat_value(case, name, column, time):
    path = os.path.join(case, "postProcessing/fmuConnectors/0/%s.dat" % name)
    head = [l for l in open(path) if l.startswith("# Time")][0][1:].split()
    rows = [list(map(float, l.split())) for l in open(path)
            if l.strip() and not l.startswith("#")]
    return min(rows, key=lambda r: abs(r[0] - time))[head.index(column)]


# The test's connectors (renderScene.sh writes them): name, kind, body A,
# A.p, body B (None: the fixed world), B.p, hinge axis in A
CONNECTORS = [
    ("spring", "spring", "floatingObject1", [-0.1, 0, 0.12], None, [-0.7, 0.5, 0.55], None),
    ("damper", "damper", "floatingObject2", [0.1, 0, 0.12], None, [0.7, 0.5, 0.55], None),
    ("hinge", "hinge", "floatingObject1", [0.2, 0, 0.17], "floatingObject2",
     [-0.2, 0, 0.17], [0, 1, 0]),
]
COLOURS = {
    "spring": lambda p: (p[..., 1] > p[..., 0] + 60) & (p[..., 1] > p[..., 2] + 40),
    "damper": lambda p: (p[..., 2] > p[..., 1] + 60) & (p[..., 0] > p[..., 1] + 20),
    "hinge": lambda p: (p[..., 0] > 150) & (p[..., 1] < 90) & (p[..., 2] > 60),
}


def segment_mask(shape, a, b):
    mask = np.zeros(shape, bool)
    steps = int(np.linalg.norm(b - a)) + 1
    for s in np.linspace(0, 1, steps + 1):
        c, r = (a + s*(b - a)).astype(int)
        if 0 <= r < shape[0] and 0 <= c < shape[1]:
            mask[r, c] = True
    return mask, steps


def check_connectors(png, none, case, time):
    """Each connector alone (png_<name>.png) against none of them: the
    pixels that differ lie along the segment between its attachment points
    (from the bodies' logged motion, independently of renderScene), a
    hinge's along its axis at the joint, and have its colour; all of them
    together (png) likewise."""
    cam = Camera(png + ".camera")
    p0 = read_png(none)
    h, w = p0.shape[:2]
    font = max(14, int(min(0.017*w, 0.05*h)))
    band = np.zeros((h, w), bool)
    band[4*font:, :] = True          # below the case name and the legend
    diagonal = math.sqrt(6.0)        # the tank, (-1 0 0) to (1 1 1)
    everywhere = np.zeros((h, w), bool)
    widest = 0
    for name, kind, body_a, p_a, body_b, p_b, axis in CONNECTORS:
        c, R = body_pose(case, body_a, time)
        P = c + R @ p_a
        if body_b is None:
            Q = np.array(p_b, float)
        else:
            c, RB = body_pose(case, body_b, time)
            Q = c + RB @ p_b
        # The points agree with the connector's own output (1 mm: the
        # output is of the step's last solve, the log of its end)
        gap = dat_value(case, name, "length", time)
        if abs(np.linalg.norm(Q - P) - gap) > 1e-3:
            fail("%s: |Q - P| = %.5f m, its output's length %.5f m"
                 % (name, np.linalg.norm(Q - P), gap))
        if kind == "hinge":
            e = R @ axis
            middle = (P + Q)/2
            P, Q = middle - 0.025*diagonal*e, middle + 0.025*diagonal*e
        a, b = cam.project([P, Q])
        # margin: the coil's radius, 0.012 diagonals, and a little, in pixels
        centre = (P + Q)/2
        scale = np.linalg.norm(cam.project([centre + 0.016*diagonal*cam.u])[0]
                               - cam.project([centre])[0])
        near, length = segment_mask((h, w), a, b)
        margin = int(math.ceil(scale)) + 2
        widest = max(widest, margin)
        alone = read_png(png[:-4] + "_" + name + ".png")
        located("%s (alone against none)" % name, differ(alone, p0) & band,
                near, margin, max(30, 2*length))
        located("%s colour" % name, COLOURS[kind](alone) & band, near, margin,
                max(20, length))
        everywhere |= near
    located("connectors (all against none)", differ(read_png(png), p0) & band,
            everywhere, widest, 200)


def add_connectors(case):
    """hingedFloatingObjects with the spring and the damper of CONNECTORS
    added, their FMUs copied by its Allrun."""
    path = os.path.join(case, "constant/dynamicMeshDict")
    text = open(path).read()
    entries = ""
    for name, kind, body, p_a, _, p_b, _ in CONNECTORS[:2]:
        entries += """
        %s
        {
            type        fmuConnector;
            fmu         "<constant>/fmu/%s.fmu";
            body        %s;
            parameters
            {
                %s
                A.p         (%s);
                B.p         (%s);
            }
        }
""" % (name, {"spring": "linearSpring", "damper": "linearDamper"}[kind], body,
       "stiffness 100; restLength 0.4; damping 0;" if kind == "spring"
       else "damping 10;", " ".join(map(str, p_a)), " ".join(map(str, p_b)))
    if text.count("    restraints\n    {\n") != 1:
        fail("%s: no restraints dictionary to add to" % path)
    with open(path, "w") as f:
        f.write(text.replace("    restraints\n    {\n",
                             "    restraints\n    {\n" + entries))
    allrun = os.path.join(case, "Allrun")
    text = open(allrun).read()
    if "copyFmus hinge\n" not in text:
        fail("%s: no 'copyFmus hinge' line" % allrun)
    with open(allrun, "w") as f:
        f.write(text.replace("copyFmus hinge\n",
                             "copyFmus hinge linearSpring linearDamper\n"))
    print("ok: spring and damper added to %s" % case)


def make_vtk(case):
    """The bridge's connector files from the lines' .dat outputs."""
    dat = os.path.join(case, "postProcessing/fmuConnectors/0")
    folder = os.path.join(case, "VTK/fmuConnectors")
    if os.path.isdir(folder):
        print("ok: VTK files written by the bridge: %s"
              % " ".join(sorted(os.listdir(folder))))
        return
    os.makedirs(folder)
    times = sorted(float(d) for d in os.listdir(case)
                   if d.replace(".", "").isdigit())
    for f in sorted(os.listdir(dat)):
        name = f[:-4]
        head = [l for l in open(os.path.join(dat, f)) if l.startswith("# Time")][0]
        cols = head[1:].split()
        rows = [list(map(float, l.split())) for l in open(os.path.join(dat, f))
                if l.strip() and not l.startswith("#")]
        n = sum(c.startswith("shape.x[") for c in cols)
        files = []
        for i, t in enumerate(times):
            row = min(rows, key=lambda r: abs(r[0] - t))
            if abs(row[0] - t) > 1e-9:
                continue
            pts = [[row[cols.index("shape.%s[%d]" % (c, k + 1))] for c in "xyz"]
                   for k in range(n)]
            vtk = "%s_%d.vtk" % (name, i)
            with open(os.path.join(folder, vtk), "w") as out:
                out.write("# vtk DataFile Version 2.0\n%s t = %g\nASCII\n"
                          "DATASET POLYDATA\nPOINTS %d double\n" % (name, t, n))
                out.writelines("%.9g %.9g %.9g\n" % tuple(q) for q in pts)
                out.write("LINES 1 %d\n%d %s\n" % (n + 1, n, " ".join(map(str, range(n)))))
                out.write("POINT_DATA %d\nSCALARS tension double 1\n"
                          "LOOKUP_TABLE default\n" % n)
                out.writelines("%.9g\n" % row[cols.index("tension")] for _ in pts)
            files.append({"name": vtk, "time": t})
        with open(os.path.join(folder, name + ".vtk.series"), "w") as out:
            json.dump({"file-series-version": "1.0", "files": files}, out)
        print("ok: %s: %d VTK files" % (name, len(files)))


def check_same(png, other, what, limit):
    """Two pictures of the same scene from different sources: at most limit
    pixels differ (by more than 30 in a channel)."""
    a, b = read_png(png), read_png(other)
    if a.shape != b.shape:
        fail("%s: %s is %s, %s is %s" % (what, png, a.shape, other, b.shape))
    n = int(differ(a, b).sum())
    if n > limit:
        fail("%s: %d pixels differ (at most %d)" % (what, n, limit))
    print("ok: %s: %d pixels differ (at most %d)" % (what, n, limit))


def main(args):
    if args[:1] == ["--"]:
        args = args[1:]
    if args[0] == "make_vtk":
        make_vtk(args[1])
    elif args[0] == "3d":
        check_3d(*args[1:6], float(args[6]), int(args[7]), int(args[8]))
    elif args[0] == "add_connectors":
        add_connectors(args[1])
    elif args[0] == "connectors":
        check_connectors(args[1], args[2], args[3], float(args[4]))
    elif args[0] == "same":
        check_same(args[1], args[2], args[3], int(args[4]))
    elif args[0] == "2d":
        check_2d(args[1], args[2], args[3], float(args[4]))
    else:
        fail("unknown check " + args[0])


if __name__ == "__main__":
    main(sys.argv[1:])

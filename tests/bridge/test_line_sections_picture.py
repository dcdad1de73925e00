"""renderScene's picture of lines of sections, drawn from a real bridge run.

The case of test_line_sections.py (a 70 m chain and a 50 m rope from a
seabed anchor to a fairlead 40 m above it, as catenary.fmu, `sections`, and
as mooringLine.fmu, `dynamic`; a uniform catenary.fmu line, `uniform`) is
run by rigidBodySim; the bridge writes each line's VTK polyline with its
point data `section` and, for mooringLine.fmu, whose joint.x/y/z are
outputs, the joint as a vertex. The case is then given a tank (blockMesh,
no flow solved) and water (alpha.water written here): a 2D tank with water
below z = -2 m, where tutorials/bin/renderScene draws each line alone, and
a 3D one without water (its translucent surface would tint the lines under
it), where it draws the mooringLine.fmu line as a tube. Each picture, at
t = 0.1 s, is read at the line's points projected through the camera
renderScene reports:

- along every piece of the polyline between two shape points of the same
  section, the pixels are that section's colour (foamfmi.scenedraw.SECTION;
  the anchor's section and a uniform line: the line colour of before);
- at the mooringLine.fmu line's joint, the joint's ball (JOINT); no ball on
  the catenary.fmu lines, which report no joint outputs.

2D pictures are drawn flat, without lighting: a section's pixel is its
colour to within 8 of 255 per channel (the PNG's 8 bits and the FXAA
smoothing at the line's edges; the window around each sample holds the
line's unsmoothed middle). 3D tubes are lit, so their pixels are told apart
by hue: the dark grey line (channels within 30 of each other), the gold
rope (red above blue by 60, green above blue by 40), the red joint (red
above green and blue by 80).
Runs under ParaView's pvpython (numpy, VTK; Debian packages paraview,
python3-paraview), renderScene under pvbatch.
"""
import os
import subprocess
import sys

import numpy as np

from foamfmi.bridgecase import Case, check, foam_file, summary
from foamfmi.scenedraw import JOINT, SECTION
from test_line_sections import MODEL, POINTS, expected_sections, read_vtk

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tutorials"))
from checkPicture import Camera, read_png  # noqa: E402  (tests/tutorials)

TIME = 0.1
LOW, HIGH, X_MIN, X_MAX = -42.0, 6.0, -110.0, 10.0  # the tank [m]
CELLS_X, CELLS_Z, WATER_LEVEL = 24, 12, -2.0


def block_mesh(two_d):
    """The tank: 2D (one cell across, its sides `empty`) or 3D, walls."""
    half = 2.0 if two_d else 20.0
    corners = [(x, y, z) for z in (LOW, HIGH) for (x, y) in
               ((X_MIN, -half), (X_MAX, -half), (X_MAX, half), (X_MIN, half))]
    vertices = " ".join("(%g %g %g)" % c for c in corners)
    sides = "frontBack { type empty; faces ((0 1 5 4) (3 7 6 2)); }" if two_d else ""
    walls = "(0 4 7 3) (1 2 6 5) (0 3 2 1) (4 5 6 7)" + ("" if two_d else " (0 1 5 4) (3 7 6 2)")
    return foam_file("blockMeshDict", f"""convertToMeters 1;
vertices ({vertices});
blocks (hex (0 1 2 3 4 5 6 7) ({CELLS_X} {1 if two_d else 4} {CELLS_Z}) simpleGrading (1 1 1));
boundary (walls {{ type wall; faces ({walls}); }} {sides});
""")


def alpha_water(two_d):
    """alpha.water at TIME: 1 in the cells below WATER_LEVEL (2D), none (3D);
    blockMesh numbers the cells x first, then y, then z."""
    dz = (HIGH - LOW) / CELLS_Z
    layers = [1 if two_d and LOW + (k + 0.5) * dz < WATER_LEVEL else 0 for k in range(CELLS_Z)]
    across = 1 if two_d else 4
    values = [v for v in layers for _ in range(CELLS_X * across)]
    empty = "frontBack { type empty; }" if two_d else ""
    text = foam_file("alpha.water", f"""dimensions [0 0 0 0 0 0 0];
internalField nonuniform List<scalar> {len(values)} ({" ".join(map(str, values))});
boundaryField {{ walls {{ type zeroGradient; }} {empty} }}
""")
    return text.replace("class dictionary;", "class volScalarField;")


def make_tank(case, two_d):
    with open(os.path.join(case.dir, "system", "blockMeshDict"), "w") as f:
        f.write(block_mesh(two_d))
    case.run_application(["blockMesh", "-case", case.dir], False)
    with open(os.path.join(case.dir, "%g" % TIME, "alpha.water"), "w") as f:
        f.write(alpha_water(two_d))


def render(case, line, png):
    """renderScene of one line; its camera line kept in png.camera."""
    render_scene = os.path.join(os.environ["FOAMFMI_DIR"], "tutorials", "bin", "renderScene")
    log = case.run_application([render_scene, "-time", "%g" % TIME, "-bodies", "none",
                                "-lines", line, "-output", png, case.dir], False)
    camera = [l for l in log.splitlines() if l.startswith("camera:")]
    if not camera:
        raise AssertionError(f"renderScene printed no camera:\n{log}")
    with open(png + ".camera", "w") as f:
        f.write(camera[0])
    return log


def vtk_line(case, name):
    """Shape points, their sections (0 from the anchor), joints."""
    with open(os.path.join(case.dir, "VTK", "fmuConnectors", f"{name}_5.vtk")) as f:
        words = f.read().split()
    n = int(words[words.index("POINTS") + 1])
    start = words.index("POINTS") + 3
    xyz = np.array(words[start:start + 3 * n], float).reshape(n, 3)
    _, fields = read_vtk(os.path.join(case.dir, "VTK", "fmuConnectors", f"{name}_5.vtk"))
    sections = [int(s) for s in fields.get("section", [0] * n)]
    return xyz[:POINTS], sections[:POINTS], xyz[POINTS:]


def windows(pixels, points, half=2):
    """The (2 half + 1)^2 pixels around each projected point."""
    for c, r in points.astype(int):
        yield pixels[max(r - half, 0):r + half + 1, max(c - half, 0):c + half + 1].reshape(-1, 3)


def exact(colour):
    target = np.array(colour) * 255
    return lambda w: np.abs(w - target).max(axis=1) <= 8


def hues():
    """The 3D tests of a lit pixel: section 0 (grey), section 1 (gold), joint."""
    grey = lambda w: (w.max(axis=1) - w.min(axis=1) <= 30) & (w.max(axis=1) < 200)
    gold = lambda w: (w[:, 0] > w[:, 2] + 60) & (w[:, 1] > w[:, 2] + 40)
    red = lambda w: w[:, 0] > np.maximum(w[:, 1], w[:, 2]) + 80
    return [grey, gold], red


def check_picture(png, xyz, sections, joints, two_d, label):
    """Each section's colour along its pieces, the joint's ball at each joint
    and none elsewhere; returns (checks, failures)."""
    pixels = read_png(png)
    camera = Camera(png + ".camera")
    tests, joint_test = ([exact(c) for c in SECTION[:2]], exact(JOINT)) if two_d else hues()
    checks = failures = 0
    for k in sorted(set(sections)):
        # Samples at 20 to 80 % of each segment within section k
        samples = [xyz[i] + s * (xyz[i + 1] - xyz[i]) for i in range(len(xyz) - 1)
                   if sections[i] == sections[i + 1] == k for s in np.linspace(0.2, 0.8, 7)]
        hits = [bool(tests[k](w).any() and not any(tests[j](w).any() for j in range(2) if j != k))
                for w in windows(pixels, camera.project(np.array(samples)))]
        checks += 1
        failures += check(f"{label}: section {k + 1} in its colour",
                          sum(hits) >= 0.9 * len(hits),
                          f"{sum(hits)} of {len(hits)} samples along its pieces")
    at_joints = [int(joint_test(w).sum()) for w in windows(pixels, camera.project(joints), 3)] \
        if len(joints) else []
    anywhere = int(joint_test(pixels.reshape(-1, 3)).sum())
    checks += 1
    if len(joints):
        failures += check(f"{label}: the joint's ball at each joint",
                          all(n >= 10 for n in at_joints),
                          f"joint colour pixels around each joint: {at_joints} (at least 10 of 49)")
    else:
        failures += check(f"{label}: no joint drawn", anywhere == 0,
                          f"{anywhere} pixels of the joint's colour")
    return checks, failures


def main():
    case = Case("lineSectionsPicture", MODEL, TIME, 0.02)
    case.run()
    lines = {name: vtk_line(case, name) for name in ("sections", "dynamic", "uniform")}
    checks = failures = 0
    # What the bridge wrote: the sections of test_line_sections, a joint
    # with mooringLine.fmu only
    for name, (xyz, sections, joints) in lines.items():
        expected = [0] * POINTS if name == "uniform" else expected_sections()
        checks += 1
        failures += check(f"{name}: VTK sections and joints", sections == expected
                          and len(joints) == (1 if name == "dynamic" else 0),
                          f"sections {sections}, {len(joints)} joints")
    for two_d in (True, False):
        make_tank(case, two_d)
        for name, (xyz, sections, joints) in lines.items():
            if not two_d and name != "dynamic":
                continue
            png = os.path.join(case.dir, f"{name}_{'2D' if two_d else '3D'}.png")
            render(case, name, png)
            c, f = check_picture(png, xyz, sections, joints, two_d,
                                 f"{name} ({'2D' if two_d else '3D'})")
            checks, failures = checks + c, failures + f
    if not failures:
        case.cleanup()
    else:
        print(f"pictures kept in {case.dir}")
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())

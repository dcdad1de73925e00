"""renderScene [OPTIONS] [CASE]

Renders a picture of a floating-body case (CASE, default .) without a
display: the free surface, the floating bodies, the mooring lines and the
other connectors (springs, dampers, hinges) at one
written time, as PNG, or at every written time as an animation.

  3D cases  the iso-surface alpha.water = 0.5 in translucent blue (the lines
            and the bodies' wetted parts show through it), seen obliquely
            from above, the tank's outline in black
  2D cases  (a non-empty `empty` patch) the water (alpha.water >= 0.5) filled
            in blue on the plane midway through the thin direction, seen from
            the side, the tank in light grey
  bodies    in orange: the patches that the mesh motion moves (`patches` in
            constant/dynamicMeshDict, sixDoFRigidBodyDisplacement patches of
            0.orig/ or 0/pointDisplacement), or those named by -bodies
  lines     in dark grey: VTK/fmuConnectors/<name>.vtk.series (legacy VTK
            polylines, one file per write time, written by the fmuConnector
            restraints) or, for a time it does not have, the line shapes
            (shape.x[i], shape.y[i], shape.z[i]) in
            postProcessing/fmuConnectors/<startTime>/<name>.dat at the row of
            the rendered time; a line of sections (the VTK file's point data
            `section`) in a colour per section from the anchor (dark grey,
            gold, teal, brown), its joints (the file's vertices) as red balls
  connectors the fmuConnector restraints without a line shape, between
            their attachment points: a spring as a green coil (a zig-zag
            in 2D), a damper as a purple cylinder and a light rod, a hinge
            as a short magenta cylinder along its axis at the joint, any
            other connector as a grey rod; one to the fixed world (no
            bodyB) ends in a dark ball at its anchor. The points are A.p,
            B.p of the restraint's parameters (constant/dynamicMeshDict, or
            the sixDoF patches of 0.orig/pointDisplacement, read as
            OpenFOAM reads them: foamDictionary -expand) placed by the
            bodies' motion: the state OpenFOAM wrote at the rendered time
            (rigidBodyMotionState, sixDoFRigidBodyMotionState, the sixDoF
            patches of pointDisplacement), or
            postProcessing/rigidBodyMotion/<body>.dat where the case has
            it (rigidBodyMotionFromLog); their kinds and numbers are listed
            below the case name
The case name and the time are printed in the top left corner. Cells that
an overset mesh blanks (cellTypes 2, holes) are left out.

Options:
  -time T          the written time to render (default: the latest)
  -output FILE     the picture (default CASE/plots/scene.png, with -time T
                   CASE/plots/scene_T.png, with -animation
                   CASE/plots/scene.gif)
  -animation       a frame at every written time; encoded to FILE (GIF, or
                   any format ffmpeg knows by FILE's extension) by ffmpeg or
                   else ImageMagick's convert; with neither, the frames are
                   kept in FILE's folder, <name>_frames/
  -fps F           animation frames per second (default: real time, kept
                   within 2-25)
  -bodies "P ..."  the body patches (names or regular expressions); "none"
                   for none
  -lines "N ..."   the connector lines to draw (default all that have a
                   shape); "none" for none
  -connectors "N ..."  the springs, dampers and hinges to draw (default
                   all); "none" for none
  -size WxH        picture size in pixels (default 1280 wide, 720 high in
                   3D, the tank's aspect in 2D)
  -help            print this help and exit

Runs under ParaView's pvbatch (Debian packages paraview, python3-paraview;
xvfb when there is no display): tutorials/bin/renderScene starts it.
It prints what it drew (lines: n of N; springs, dampers, hinges: n of N)
and the camera it used (position, focal point, view up, view angle or
parallel scale), so that positions in the scene can be located in the
picture.
"""

import math
import os
import re
import shutil
import subprocess
import sys

# The case's dictionaries and mooring lines: the project's package
# (python/foamfmi, on PYTHONPATH from etc/bashrc)
try:
    from foamfmi import cli, connectorscene
    from foamfmi.dictionary import DictionaryError
    from foamfmi.scene import (connector_lines, fail, moving_patch_names, near,
                               read_boundary, select_patches, up_direction)
    from foamfmi.scenedraw import Scene
except ImportError as err:
    hint = (" (source etc/bashrc: it puts the project's python/ on PYTHONPATH)"
            if err.name == "foamfmi" else "")
    sys.exit("renderScene: %s%s" % (err, hint))


# ---------------------------------------------------------------- options

def parse_options(argv):
    p = cli.parser("renderScene", __doc__)
    # the options with a value, described above: (option, its value)
    for option, value in (("-time", "T"), ("-output", "FILE"), ("-fps", "F"),
                          ("-bodies", '"P ..."'), ("-lines", '"N ..."'),
                          ("-connectors", '"N ..."'), ("-size", "WxH")):
        p.add_argument(option, metavar=value)
    p.add_argument("-animation", action="store_true")
    cli.add_case(p)
    opts = vars(p.parse_args(argv))
    if opts["time"] is not None and opts["animation"]:
        fail("-time and -animation exclude each other")
    if opts["time"] is not None and opts["time"] != "latest":
        opts["time"] = positive_number("-time", opts["time"], allow_zero=True)
    if opts["fps"] is not None:
        opts["fps"] = positive_number("-fps", opts["fps"])
    if opts["size"] is not None:
        m = re.fullmatch(r"(\d+)x(\d+)", opts["size"])
        if not m or int(m.group(1)) < 64 or int(m.group(2)) < 64:
            fail("-size: expected WIDTHxHEIGHT in pixels, each at least 64,"
                 " got '%s'" % opts["size"])
        opts["size"] = (int(m.group(1)), int(m.group(2)))
    for key in ("bodies", "lines", "connectors"):
        if opts[key] is not None:
            opts[key] = [] if opts[key].strip() == "none" else opts[key].split()
    return opts


def positive_number(option, text, allow_zero=False):
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not (value > 0 or (allow_zero and value == 0)) or math.isinf(value):
        fail("%s: expected a number %s 0, got '%s'"
             % (option, ">=" if allow_zero else ">", text))
    return value


# --------------------------------------------------------------- main

def main():
    argv = sys.argv[1:]
    if argv[:1] == ["--"]:      # the end of pvbatch's options
        argv = argv[1:]
    opts = parse_options(argv)
    case = os.path.abspath(opts["case"])
    if not os.path.isfile(os.path.join(case, "system/controlDict")):
        fail("%s: not an OpenFOAM case (no system/controlDict)" % opts["case"])
    patches = read_boundary(case)
    try:
        trees = connectorscene.read_dictionaries(case)
    except DictionaryError as error:
        sys.stderr.write("renderScene: warning: %s: bodies (use -bodies), springs, dampers"
                         " and hinges not drawn\n" % error)
        trees = None
    if opts["bodies"] is None:
        bodies = select_patches(moving_patch_names(trees or {}), patches, None)
    else:
        bodies = select_patches(opts["bodies"], patches, "-bodies")
    lines, line_names = connector_lines(case, opts["lines"])
    two_d = any(p[1] == "empty" and p[2] > 0 for p in patches)

    scene = Scene(case, bodies, two_d, up_direction(case))
    times = scene.times
    if not times:
        fail("%s: no written time" % opts["case"])
    if opts["animation"]:
        render_times = times
    elif opts["time"] in (None, "latest"):
        render_times = [times[-1]]
    else:
        render_times = [t for t in times if near(t, opts["time"])]
        if not render_times:
            fail("-time %g: not a written time of the case; written: %s"
                 % (opts["time"], " ".join("%g" % t for t in times)))
    connectors, totals, motion = read_connectors(case, trees, lines.names(),
                                                 opts["connectors"], render_times)
    output = opts["output"] or default_output(case, opts)
    os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
    scene.set_size(opts["size"])

    def draw(time, png):
        shapes = []
        for name in line_names:
            shape = lines.polydata(name, time)
            if shape is not None:
                shapes.append(shape)
        placed = []
        for c in connectors:
            where = connectorscene.positions(c, motion, time)
            if where is not None:
                placed.append((c.kind,) + where + (c.body_b is None,))
        scene.render(time, shapes, png, placed)
        return len(shapes), placed

    if not opts["animation"]:
        n, placed = draw(render_times[0], output)
        counts = ["lines: %d of %d" % (n, len(line_names))]
        for kind in connectorscene.ORDER:
            total = totals.get(kind, 0)
            if total or kind != "connector":
                counts.append("%ss: %d of %d" % (
                    kind, sum(1 for p in placed if p[0] == kind), total))
        print("renderScene: wrote %s (t = %g s; bodies: %s; %s)"
              % (output, render_times[0], " ".join(bodies) or "none",
                 "; ".join(counts)))
    else:
        scene.keep_levels = True
        animate(render_times, output, opts["fps"], draw)
    print(scene.camera_text())


def read_connectors(case, trees, line_names, wanted, times):
    """The connectors without a line shape (springs, dampers, hinges) to
    draw, the case's number of each kind and the bodies' motion that places
    them at the times to render (trees: the case's dictionaries,
    connectorscene.read_dictionaries; None when they could not be read:
    the picture is drawn without them)."""
    found, placements = [], {}
    if trees is not None:
        try:
            found, placements = connectorscene.read_connectors(case, trees)
        except DictionaryError as error:
            sys.stderr.write("renderScene: warning: %s: springs, dampers and hinges"
                             " not drawn\n" % error)
    found = [c for c in found if c.name not in line_names and c.kind != "line"]
    names = [c.name for c in found]
    totals = {}
    for c in found:
        totals[c.kind] = totals.get(c.kind, 0) + 1
    if wanted is not None:
        for name in wanted:
            if name not in names:
                fail("-connectors: no spring, damper or hinge '%s' in the case;"
                     " connectors: %s" % (name, " ".join(names) or "none"))
        found = [c for c in found if c.name in wanted]
    motion = connectorscene.BodyMotion(case, placements,
                                       (trees or {}).get("constant/dynamicMeshDict"))
    for c in found:
        for body in (c.body_a, c.body_b):
            if body and not motion.has_motion(body, times):
                sys.stderr.write(
                    "renderScene: warning: %s: no motion of %s (neither its state in"
                    " the written times nor postProcessing/rigidBodyMotion/%s.dat):"
                    " drawn at the start only\n" % (c.name, body, body))
    return found, totals, motion


def default_output(case, opts):
    if opts["animation"]:
        name = "scene.gif"
    elif opts["time"] in (None, "latest"):
        name = "scene.png"
    else:
        name = "scene_%g.png" % opts["time"]
    return os.path.join(case, "plots", name)


def animate(times, output, fps, draw):
    """A frame per time into <output>_frames/, then encoded to output."""
    base = os.path.splitext(output)[0]
    frames = base + "_frames"
    shutil.rmtree(frames, ignore_errors=True)
    os.makedirs(frames)
    for i, t in enumerate(times):
        draw(t, os.path.join(frames, "frame_%04d.png" % i))
    if fps is None:
        steps = [b - a for a, b in zip(times, times[1:])]
        real_time = 1.0/(sum(steps)/len(steps)) if steps else 2.0
        fps = min(25.0, max(2.0, real_time))
    pattern = os.path.join(frames, "frame_%04d.png")
    if shutil.which("ffmpeg"):
        # One palette for all frames: GIF has 256 colours
        command = ["ffmpeg", "-loglevel", "error", "-y", "-framerate",
                   "%g" % fps, "-i", pattern]
        if output.lower().endswith(".gif"):
            command += ["-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse"]
        command.append(output)
    elif shutil.which("convert"):
        command = ["convert", "-delay", "%d" % round(100.0/fps), "-loop", "0"]
        command += [os.path.join(frames, f) for f in sorted(os.listdir(frames))]
        command.append(output)
    else:
        print("renderScene: %d frames in %s (neither ffmpeg nor ImageMagick's"
              " convert found to encode them)" % (len(times), frames))
        return
    if subprocess.call(command) != 0:
        fail("%s failed; the frames are kept in %s" % (command[0], frames))
    shutil.rmtree(frames)
    print("renderScene: wrote %s (%d frames, t = %g to %g s, %g frames/s)"
          % (output, len(times), times[0], times[-1], fps))


if __name__ == "__main__":
    main()

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
            the rendered time
  connectors the fmuConnector restraints without a line shape, between
            their attachment points: a spring as a green coil (a zig-zag
            in 2D), a damper as a purple cylinder and a light rod, a hinge
            as a short magenta cylinder along its axis at the joint, any
            other connector as a grey rod; one to the fixed world (no
            bodyB) ends in a dark ball at its anchor. The points are A.p,
            B.p of the restraint's parameters (constant/dynamicMeshDict, or
            the sixDoF patches of 0.orig/pointDisplacement) placed by the
            bodies' motion, postProcessing/rigidBodyMotion/<body>.dat
            (rigidBodyMotionFromLog, which the tutorials' Allrun runs);
            their kinds and numbers are listed below the case name
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

WATER = (0.16, 0.42, 0.85)
WATER_TROUGH, WATER_CREST = (0.04, 0.22, 0.62), (0.42, 0.66, 0.98)
WATER_OPACITY = 0.65
BODY = (0.96, 0.47, 0.08)
LINE = (0.12, 0.12, 0.12)
# Springs, dampers (cylinder, rod), hinges, other connectors, fixed anchors
CONNECTOR = {"spring": (0.05, 0.6, 0.2), "damper": (0.5, 0.2, 0.8),
             "rod": (0.75, 0.65, 0.9), "hinge": (0.85, 0.05, 0.45),
             "connector": (0.35, 0.35, 0.35), "anchor": (0.12, 0.12, 0.12)}
TANK_2D = (0.93, 0.93, 0.93)
OUTLINE = (0.0, 0.0, 0.0)


# The case's dictionaries and mooring lines: the project's package
# (python/foamfmi, on PYTHONPATH from etc/bashrc)
try:
    from foamfmi import cli, connectorscene
    from foamfmi.dictionary import DictionaryError
    from foamfmi.scene import (connector_lines, fail, moving_patch_names, near,
                               polyline, read_boundary, select_patches,
                               up_direction)
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


# ------------------------------------------------------------ the scene

def load_vtk():
    """ParaView's VTK modules, imported only once the options are checked
    (-help and option errors need no ParaView)."""
    from types import SimpleNamespace
    import vtkmodules.vtkRenderingOpenGL2   # noqa: F401  the render window
    import vtkmodules.vtkRenderingFreeType  # noqa: F401  the text
    from vtkmodules.vtkCommonCore import vtkLogger, vtkLookupTable
    from vtkmodules.vtkCommonDataModel import (
        vtkCompositeDataSet, vtkDataObject, vtkPlane)
    from vtkmodules.vtkFiltersCore import (
        vtkCellDataToPointData, vtkClipPolyData, vtkContourFilter, vtkCutter,
        vtkElevationFilter, vtkPolyDataNormals, vtkThreshold, vtkTubeFilter)
    from vtkmodules.vtkFiltersGeneral import vtkContourTriangulator
    from vtkmodules.vtkFiltersModeling import vtkOutlineFilter
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOGeometry import vtkOpenFOAMReader
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkIOParallel import vtkPOpenFOAMReader
    from vtkmodules.vtkRenderingCore import (
        vtkActor, vtkLightKit, vtkPolyDataMapper, vtkRenderer,
        vtkRenderWindow, vtkTextActor, vtkWindowToImageFilter)
    # Errors and warnings, not the filters' progress notes
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
    return SimpleNamespace(**locals())


def latest_time(folder):
    """The latest time folder's time in folder (-1 when none)."""
    latest = -1.0
    if os.path.isdir(folder):
        for entry in os.listdir(folder):
            try:
                latest = max(latest, float(entry))
            except ValueError:
                pass
    return latest


def cross(a, b):
    return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2],
            a[0]*b[1] - a[1]*b[0]]


def unit(a):
    norm = math.sqrt(sum(v*v for v in a))
    return [v/norm for v in a]


def axis(i):
    return [1.0 if j == i else 0.0 for j in range(3)]


class Scene:
    """The case read by VTK's OpenFOAM reader, drawn by one render window."""

    def __init__(self, case, bodies, two_d, up):
        self.vtk = vtk = load_vtk()
        self.case_name = os.path.basename(case)
        self.bodies, self.two_d = bodies, two_d
        # A case run in parallel and not (yet) reconstructed: read its
        # processor folders
        if latest_time(os.path.join(case, "processor0")) > latest_time(case):
            reader = vtk.vtkPOpenFOAMReader()
            reader.SetCaseType(vtk.vtkPOpenFOAMReader.DECOMPOSED_CASE)
        else:
            reader = vtk.vtkOpenFOAMReader()
        self.reader = reader
        reader.SetFileName(os.path.join(case, "system/controlDict"))
        reader.SkipZeroTimeOff()
        reader.CreateCellToPointOff()   # interpolated below, without holes
        reader.DecomposePolyhedraOn()
        reader.UpdateInformation()
        values = reader.GetTimeValues()
        self.times = ([values.GetValue(i)
                       for i in range(values.GetNumberOfTuples())]
                      if values is not None else [])
        reader.DisableAllPatchArrays()
        reader.SetPatchArrayStatus("internalMesh", 1)
        for body in bodies:
            reader.SetPatchArrayStatus("patch/" + body, 1)
        fields = [reader.GetCellArrayName(i)
                  for i in range(reader.GetNumberOfCellArrays())]
        if "alpha.water" not in fields:
            fail("%s: no alpha.water field in the written times" % case)
        reader.DisableAllCellArrays()
        reader.DisableAllPointArrays()
        reader.DisableAllLagrangianArrays()
        reader.SetCellArrayStatus("alpha.water", 1)
        # Overset meshes: cellTypes 2 marks the holes, whose alpha is stale
        self.overset = "cellTypes" in fields
        if self.overset:
            reader.SetCellArrayStatus("cellTypes", 1)

        self.up = up
        self.renderer = vtk.vtkRenderer()
        self.renderer.SetBackground(1.0, 1.0, 1.0)
        # Key, fill and back lights: faces away from the camera keep shape
        vtk.vtkLightKit().AddLightsToRenderer(self.renderer)
        # Translucent water in front of lines and bodies: depth peeling
        self.renderer.SetUseDepthPeeling(1)
        self.renderer.SetMaximumNumberOfPeels(8)
        self.renderer.SetUseFXAA(True)
        self.window = vtk.vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetAlphaBitPlanes(1)
        self.window.SetMultiSamples(0)
        self.window.AddRenderer(self.renderer)
        self.size = None
        self.camera_set = False
        self.levels, self.keep_levels = None, False

    # -- geometry

    def read(self, time):
        """The internal mesh and the body patches at `time`."""
        self.reader.UpdateTimeStep(time)
        output = self.reader.GetOutput()
        mesh, patches = None, {}
        for i in range(output.GetNumberOfBlocks()):
            name = output.GetMetaData(i).Get(self.vtk.vtkCompositeDataSet.NAME())
            block = output.GetBlock(i)
            if name == "internalMesh":
                mesh = block
            elif name == "boundary":
                for j in range(block.GetNumberOfBlocks()):
                    meta = block.GetMetaData(j)
                    patches[meta.Get(self.vtk.vtkCompositeDataSet.NAME())] = \
                        block.GetBlock(j)
        if mesh is None or mesh.GetNumberOfCells() == 0:
            fail("%s: no internal mesh read at t = %g" % (self.case_name, time))
        return mesh, [patches[b] for b in self.bodies if b in patches]

    def water_points(self, mesh):
        """alpha.water on the points, from the cells the flow is solved in."""
        vtk = self.vtk
        source = mesh
        if self.overset:
            threshold = vtk.vtkThreshold()
            threshold.SetInputData(mesh)
            threshold.SetInputArrayToProcess(
                0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_CELLS, "cellTypes")
            threshold.SetLowerThreshold(-0.5)
            threshold.SetUpperThreshold(1.5)
            threshold.SetThresholdFunction(vtk.vtkThreshold.THRESHOLD_BETWEEN)
            threshold.Update()
            source = threshold.GetOutput()
        to_points = vtk.vtkCellDataToPointData()
        to_points.SetInputData(source)
        to_points.Update()
        data = to_points.GetOutput()
        data.GetPointData().SetActiveScalars("alpha.water")
        return data

    def mid_plane(self, data):
        """The plane midway through the thin direction of a 2D case."""
        plane = self.vtk.vtkPlane()
        plane.SetOrigin(self.centre)
        plane.SetNormal(self.normal)
        cut = self.vtk.vtkCutter()
        cut.SetInputData(data)
        cut.SetCutFunction(plane)
        cut.Update()
        return cut.GetOutput()

    def add(self, data, colour, opacity=1.0, width=None, offset=0.0,
            shades=None):
        """An actor for polydata; offset: towards the camera in 2D views, in
        units of the tank's size, so that the layers do not fight; shades:
        two colours between which the data's scalars, 0 to 1, are drawn."""
        mapper = self.vtk.vtkPolyDataMapper()
        mapper.SetInputData(data)
        mapper.ScalarVisibilityOff()
        if shades:
            table = self.vtk.vtkLookupTable()
            table.SetNumberOfTableValues(64)
            for i in range(64):
                s = i/63.0
                table.SetTableValue(i, *[(1 - s)*a + s*b
                                         for a, b in zip(*shades)], 1.0)
            mapper.SetLookupTable(table)
            mapper.SetScalarRange(0.0, 1.0)
            mapper.ScalarVisibilityOn()
        actor = self.vtk.vtkActor()
        actor.SetMapper(mapper)
        prop = actor.GetProperty()
        prop.SetColor(colour)
        prop.SetOpacity(opacity)
        if self.two_d:
            prop.LightingOff()  # flat, in its own colour: a drawing
        else:
            prop.SetAmbient(0.2)
        if width:
            prop.SetLineWidth(width)
        if offset:
            actor.SetPosition([-v*offset*self.diagonal for v in self.normal])
        self.renderer.AddActor(actor)
        return prop

    def tube(self, points, radius, sides=12):
        """A capped tube of radius (in units of the tank's diagonal) along
        the polyline through points."""
        tube = self.vtk.vtkTubeFilter()
        tube.SetInputData(polyline(points))
        tube.SetRadius(radius*self.diagonal)
        tube.SetNumberOfSides(sides)
        tube.CappingOn()
        tube.Update()
        return tube.GetOutput()

    def add_connectors(self, connectors):
        """Springs (a coil), dampers (a cylinder and its rod), hinges (a
        short cylinder along the axis at the joint), other connectors (a
        rod) between their attachment points P and Q; a fixed anchor (no
        body B) as a ball. In 2D the spring is a zig-zag in the view plane
        and all is drawn flat in front of the bodies."""
        offset = 0.0025 if self.two_d else 0.0
        shapes = connectorscene      # the polylines' points
        for kind, P, Q, axis, fixed in connectors:
            length = math.dist(P, Q)
            if kind == "spring":
                radius = min(0.012*self.diagonal, 0.15*length)
                points = shapes.coil(P, Q, radius, flat_normal=self.normal
                                     if self.two_d else None)
                parts = [(points, 0.0022, "spring")]
            elif kind == "damper":
                cylinder, rod = shapes.damper(P, Q)
                parts = [(rod, 0.003, "rod"), (cylinder, 0.008, "damper")]
            elif kind == "hinge":
                parts = [(shapes.hinge(P, Q, axis, 0.05*self.diagonal),
                          0.008, "hinge")]
            else:
                parts = [([P, Q], 0.0025, "connector")]
            for points, radius, colour in parts:
                self.add(self.tube(points, radius, 20), CONNECTOR[colour],
                         offset=offset)
            if fixed:
                ball = self.vtk.vtkSphereSource()
                ball.SetCenter(Q)
                ball.SetRadius(0.006*self.diagonal)
                ball.SetThetaResolution(16)
                ball.SetPhiResolution(12)
                ball.Update()
                self.add(ball.GetOutput(), CONNECTOR["anchor"], offset=offset)

    def add_legend(self, connectors, font):
        """The kinds of connectors drawn, each in its colour, below the
        case name."""
        x = font//2
        for kind in connectorscene.ORDER:
            n = sum(1 for c in connectors if c[0] == kind)
            if not n:
                continue
            label = "%s%s" % (kind, "s" if n > 1 else "")
            text = self.vtk.vtkTextActor()
            text.SetInput(("%d " % n if n > 1 else "") + label)
            prop = text.GetTextProperty()
            prop.SetFontSize(int(0.8*font))
            prop.SetColor(CONNECTOR[kind])
            prop.BoldOn()
            text.SetDisplayPosition(x, self.size[1] - 2*font - font)
            self.renderer.AddActor2D(text)
            x += int(0.8*font*0.62*(len(text.GetInput()) + 2))

    def build(self, time, lines, connectors=()):
        vtk = self.vtk
        self.renderer.RemoveAllViewProps()
        mesh, bodies = self.read(time)
        if not self.camera_set:
            self.set_geometry(mesh.GetBounds())
        water = self.water_points(mesh)
        if self.two_d:
            section = self.mid_plane(water)
            self.add(section, TANK_2D, offset=-0.002)
            clip = vtk.vtkClipPolyData()
            clip.SetInputData(section)
            clip.SetValue(0.5)          # keeps alpha.water >= 0.5
            clip.Update()
            self.add(clip.GetOutput(), WATER)
            outline = vtk.vtkOutlineFilter()
            outline.SetInputData(section)
            outline.Update()
            self.add(outline.GetOutput(), OUTLINE, width=2, offset=0.003)
            for body in bodies:
                loop = self.mid_plane(body)
                fill = vtk.vtkContourTriangulator()
                fill.SetInputData(loop)
                fill.Update()
                self.add(fill.GetOutput(), BODY, offset=0.001)
                self.add(loop, [0.6*c for c in BODY], width=2, offset=0.0015)
            for line in lines:
                self.add(line, LINE, width=3, offset=0.002)
            self.add_connectors(connectors)
        else:
            contour = vtk.vtkContourFilter()
            contour.SetInputData(water)
            contour.SetInputArrayToProcess(
                0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS,
                "alpha.water")
            contour.SetValue(0, 0.5)
            normals = vtk.vtkPolyDataNormals()
            normals.SetInputConnection(contour.GetOutputPort())
            normals.SplittingOff()
            normals.Update()
            prop = self.add(self.elevation(normals.GetOutput()), WATER,
                            opacity=WATER_OPACITY,
                            shades=(WATER_TROUGH, WATER_CREST))
            prop.SetSpecular(0.3)
            prop.SetSpecularPower(30)
            outline = vtk.vtkOutlineFilter()
            outline.SetInputData(mesh)
            outline.Update()
            self.add(outline.GetOutput(), OUTLINE, width=2)
            for body in bodies:
                self.add(body, BODY)
            for line in lines:
                tube = vtk.vtkTubeFilter()
                tube.SetInputData(line)
                tube.SetRadius(0.003*self.diagonal)
                tube.SetNumberOfSides(10)
                tube.CappingOn()
                tube.Update()
                self.add(tube.GetOutput(), LINE)
            self.add_connectors(connectors)
        text = vtk.vtkTextActor()
        text.SetInput("%s    t = %g s" % (self.case_name, time))
        font = max(14, int(min(0.017*self.size[0], 0.05*self.size[1])))
        text.GetTextProperty().SetFontSize(font)
        text.GetTextProperty().SetColor(0.0, 0.0, 0.0)
        text.SetDisplayPosition(font//2, self.size[1] - font - font//2)
        self.renderer.AddActor2D(text)
        self.add_legend(connectors, font)

    def elevation(self, surface):
        """The surface with its height as scalars, 0 to 1 from trough to
        crest: the waves show in a view from above. The scale spans at
        least 4 % of the tank's height, so that still water looks still;
        in an animation it is the first frame's, so that shades compare."""
        heights = [sum(p*u for p, u in zip(surface.GetPoint(i), self.up))
                   for i in range(surface.GetNumberOfPoints())]
        if not heights:
            return surface
        if self.levels is None or not self.keep_levels:
            self.levels = ((min(heights) + max(heights))/2, max(
                (max(heights) - min(heights))/2, 0.02*self.extent[1]))
        middle, half = self.levels
        level = self.vtk.vtkElevationFilter()
        level.SetInputData(surface)
        level.SetLowPoint([middle*u - half*u for u in self.up])
        level.SetHighPoint([middle*u + half*u for u in self.up])
        level.Update()
        return level.GetOutput()

    # -- camera and picture

    def set_geometry(self, bounds):
        """Tank size, view axes and, unless given, the picture size."""
        self.bounds = bounds
        lo, hi = bounds[0::2], bounds[1::2]
        extent = [h - l for l, h in zip(lo, hi)]
        self.centre = [(l + h)/2 for l, h in zip(lo, hi)]
        self.diagonal = math.sqrt(sum(e*e for e in extent))
        up_axis = max(range(3), key=lambda i: abs(self.up[i]))
        horizontal = [i for i in range(3) if i != up_axis]
        if self.two_d:
            thin = min(horizontal, key=lambda i: extent[i])
            along = [i for i in horizontal if i != thin][0]
        else:
            along = max(horizontal, key=lambda i: extent[i])
        # Seen from the side where `along` points to the right
        self.along = axis(along)
        self.normal = unit(cross(self.up, self.along))
        self.extent = (extent[along], extent[up_axis])
        if self.size is None:
            if self.two_d:
                height = 1280*self.extent[1]/self.extent[0]*1.03/0.91
                self.size = (1280, 2*int(min(1280, max(320, height))/2))
            else:
                self.size = (1280, 720)
        self.window.SetSize(*self.size)

    def set_size(self, size):
        self.size = size

    def set_camera(self):
        camera = self.renderer.GetActiveCamera()
        camera.SetFocalPoint(self.centre)
        camera.SetViewUp(self.up)
        if self.two_d:
            # The tank fills the width, or the height less a band of 7 % at
            # the top for the time and 2 % at the bottom
            aspect = self.size[0]/self.size[1]
            scale = max(1.03*self.extent[0]/2/aspect, self.extent[1]/2/0.91)
            focus = [c + 0.05*scale*u for c, u in zip(self.centre, self.up)]
            camera.ParallelProjectionOn()
            camera.SetParallelScale(scale)
            camera.SetFocalPoint(focus)
            camera.SetPosition([c - 2*self.diagonal*n
                                for c, n in zip(focus, self.normal)])
        else:
            # Obliquely from above, in front, a little from the generator side
            direction = unit([-0.3*a - 1.0*n + 0.65*u for a, n, u
                              in zip(self.along, self.normal, self.up)])
            camera.SetPosition([c + self.diagonal*d
                                for c, d in zip(self.centre, direction)])
            self.renderer.ResetCamera(self.bounds)   # the tank only
            camera.SetFocalPoint(self.centre)
            camera.Zoom(0.92/self.largest_view_coordinate())
        self.renderer.ResetCameraClippingRange()
        self.camera_set = True

    def largest_view_coordinate(self):
        """The tank's corners' largest view coordinate (1: the picture's
        edge)."""
        largest = 0.0
        for corner in range(8):
            point = [self.bounds[2*i + (corner >> i & 1)] for i in range(3)]
            self.renderer.SetWorldPoint(point + [1.0])
            self.renderer.WorldToView()
            view = self.renderer.GetViewPoint()
            largest = max(largest, abs(view[0]), abs(view[1]))
        return largest

    def render(self, time, lines, png, connectors=()):
        vtk = self.vtk
        self.build(time, lines, connectors)
        if not self.camera_set:
            self.set_camera()
        self.renderer.ResetCameraClippingRange()
        self.window.Render()
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.SetInputBufferTypeToRGB()
        grab.ReadFrontBufferOff()
        grab.Update()
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(png)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        if writer.GetErrorCode():
            fail("cannot write %s" % png)

    def camera_text(self):
        camera = self.renderer.GetActiveCamera()
        return ("camera: position %s focalPoint %s viewUp %s viewAngle %.9g"
                " parallelProjection %d parallelScale %.9g size %d %d"
                % (" ".join("%.9g" % v for v in camera.GetPosition()),
                   " ".join("%.9g" % v for v in camera.GetFocalPoint()),
                   " ".join("%.9g" % v for v in camera.GetViewUp()),
                   camera.GetViewAngle(), camera.GetParallelProjection(),
                   camera.GetParallelScale(), self.size[0], self.size[1]))
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
    if opts["bodies"] is None:
        bodies = select_patches(moving_patch_names(case), patches, None)
    else:
        bodies = select_patches(opts["bodies"], patches, "-bodies")
    lines, line_names = connector_lines(case, opts["lines"])
    connectors, totals, motion = read_connectors(case, lines.names(),
                                                 opts["connectors"])
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


def read_connectors(case, line_names, wanted):
    """The connectors without a line shape (springs, dampers, hinges) to
    draw, the case's number of each kind and the bodies' motion that places
    them. A dictionary that cannot be read is a warning: the picture is
    drawn without them."""
    try:
        found, placements = connectorscene.read_connectors(case)
    except DictionaryError as error:
        sys.stderr.write("renderScene: warning: %s: springs, dampers and hinges"
                         " not drawn\n" % error)
        found, placements = [], {}
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
    motion = connectorscene.BodyMotion(case, placements)
    for c in found:
        for body in (c.body_a, c.body_b):
            if body and not motion.has_rows(body):
                sys.stderr.write(
                    "renderScene: warning: %s: no motion of %s (postProcessing/"
                    "rigidBodyMotion/%s.dat, rigidBodyMotionFromLog writes it):"
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

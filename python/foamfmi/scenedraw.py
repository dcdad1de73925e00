"""renderScene's scene (tutorials/bin/renderScene.py): a case read by
VTK's OpenFOAM reader (its processor folders when not reconstructed; the
holes of an overset mesh left out) and drawn: the water (an iso-surface
shaded by height in 3D, filled on the mid plane in 2D), the tank's outline,
the bodies, the mooring lines (a line of sections in a colour per section,
its joints as balls), the springs, dampers and hinges, the case name, time
and legend. The camera and the picture: foamfmi.sceneview.
Runs under ParaView's pvbatch.
"""

import math
import os

from foamfmi import connectorscene
from foamfmi.scene import fail, polyline
from foamfmi.sceneview import SceneView, load_vtk

WATER = (0.16, 0.42, 0.85)
WATER_TROUGH, WATER_CREST = (0.04, 0.22, 0.62), (0.42, 0.66, 0.98)
WATER_OPACITY = 0.65
BODY = (0.96, 0.47, 0.08)
LINE = (0.12, 0.12, 0.12)
# A line's sections from the anchor (B.p; the VTK field `section`, 0 at
# B.p), repeated past the fourth: the first is LINE, so a uniform line keeps
# its colour; the joints' balls
SECTION = (LINE, (0.95, 0.7, 0.0), (0.0, 0.6, 0.6), (0.55, 0.35, 0.15))
JOINT = (0.85, 0.1, 0.1)
# Springs, dampers (cylinder, rod), hinges, other connectors, fixed anchors
CONNECTOR = {"spring": (0.05, 0.6, 0.2), "damper": (0.5, 0.2, 0.8),
             "rod": (0.75, 0.65, 0.9), "hinge": (0.85, 0.05, 0.45),
             "connector": (0.35, 0.35, 0.35), "anchor": (0.12, 0.12, 0.12)}
TANK_2D = (0.93, 0.93, 0.93)
OUTLINE = (0.0, 0.0, 0.0)


def section_colour(k):
    return SECTION[k % len(SECTION)]


def line_parts(line):
    """A connector line's polydata (VTK/fmuConnectors/): the points of its
    polyline in order, each point's section (the point field `section`; None
    without it) and the joints (its vertices, from B.p on)."""
    points = line.GetPoints()
    ids = []
    cells = line.GetLines()
    if cells is not None and cells.GetNumberOfCells():
        from vtkmodules.vtkCommonCore import vtkIdList
        cell = vtkIdList()
        cells.InitTraversal()
        cells.GetNextCell(cell)
        ids = [cell.GetId(i) for i in range(cell.GetNumberOfIds())]
    field = line.GetPointData().GetArray("section")
    sections = ([int(field.GetTuple1(i)) for i in ids]
                if field is not None else None)
    joints = []
    verts = line.GetVerts()
    if verts is not None:
        data = verts.GetData()
        values = [int(data.GetTuple1(i))
                  for i in range(data.GetNumberOfTuples())]
        while values:           # (count, id, ...) per vertex cell
            count = values[0]
            joints += [points.GetPoint(i) for i in values[1:1 + count]]
            values = values[1 + count:]
    return [points.GetPoint(i) for i in ids], sections, joints


def section_pieces(points, sections, joints=()):
    """[(section, points)]: the polyline cut where its points' sections
    change. The segment across a change holds the joint(s) between them:
    cut there when `joints` has them (joint k between sections k - 1 and k,
    k from 1), else at equal parts of the segment (the joint lies somewhere
    on it)."""
    pieces = [(sections[0], [list(points[0])])]
    for i in range(1, len(points)):
        a, b = sections[i - 1], sections[i]
        p, q = points[i - 1], points[i]
        step = 1 if b > a else -1
        for m, k in enumerate(range(a, b, step), start=1):
            joint = max(k, k + step)        # the joint between k and k + step
            if joint - 1 < len(joints):
                cut = list(joints[joint - 1])
            else:
                f = m/(abs(b - a) + 1)
                cut = [(1 - f)*u + f*v for u, v in zip(p, q)]
            pieces[-1][1].append(cut)
            pieces.append((k + step, [cut]))
        pieces[-1][1].append(list(q))
    return pieces


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


class Scene(SceneView):
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
                self.add(self.ball(Q), CONNECTOR["anchor"], offset=offset)

    def ball(self, centre):
        """A ball at centre, of radius 0.006 of the tank's diagonal."""
        ball = self.vtk.vtkSphereSource()
        ball.SetCenter(centre)
        ball.SetRadius(0.006*self.diagonal)
        ball.SetThetaResolution(16)
        ball.SetPhiResolution(12)
        ball.Update()
        return ball.GetOutput()

    def add_lines(self, lines):
        """The connector lines in LINE's colour; a line of sections in a
        colour per section, a ball at each joint. Returns the sections and
        the number of joints drawn."""
        drawn, n = set(), 0
        for line in lines:
            points, sections, joints = line_parts(line)
            if not sections or (len(set(sections)) == 1 and not joints):
                self.draw_line(line, LINE)
                continue
            for k, piece in section_pieces(points, sections, joints):
                self.draw_line(polyline(piece), section_colour(k))
            for joint in joints:
                self.add(self.ball(joint), JOINT,
                         offset=0.0025 if self.two_d else 0.0)
            drawn |= set(sections)
            n += len(joints)
        return drawn, n

    def draw_line(self, data, colour):
        """A polyline: 3 pixels wide in 2D, a tube in 3D."""
        if self.two_d:
            self.add(data, colour, width=3, offset=0.002)
            return
        tube = self.vtk.vtkTubeFilter()
        tube.SetInputData(data)
        tube.SetRadius(0.003*self.diagonal)
        tube.SetNumberOfSides(10)
        tube.CappingOn()
        tube.Update()
        self.add(tube.GetOutput(), colour)

    def add_legend(self, connectors, font, sections=(), joints=0):
        """The kinds of connectors drawn, each in its colour, then the lines'
        sections (numbered from the anchor, as the FMUs' section<k>) and
        joints, below the case name."""
        items = []
        for kind in connectorscene.ORDER:
            n = sum(1 for c in connectors if c[0] == kind)
            if n:
                items.append((("%d " % n if n > 1 else "") + kind
                              + ("s" if n > 1 else ""), CONNECTOR[kind]))
        items += [("section %d" % (k + 1), section_colour(k))
                  for k in sorted(sections)]
        if joints:
            items.append(("joint%s" % ("s" if joints > 1 else ""), JOINT))
        x = font//2
        for label, colour in items:
            text = self.vtk.vtkTextActor()
            text.SetInput(label)
            prop = text.GetTextProperty()
            prop.SetFontSize(int(0.8*font))
            prop.SetColor(colour)
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
            sections, joints = self.add_lines(lines)
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
            sections, joints = self.add_lines(lines)
            self.add_connectors(connectors)
        text = vtk.vtkTextActor()
        text.SetInput("%s    t = %g s" % (self.case_name, time))
        font = max(14, int(min(0.017*self.size[0], 0.05*self.size[1])))
        text.GetTextProperty().SetFontSize(font)
        text.GetTextProperty().SetColor(0.0, 0.0, 0.0)
        text.SetDisplayPosition(font//2, self.size[1] - font - font//2)
        self.renderer.AddActor2D(text)
        self.add_legend(connectors, font, sections, joints)

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

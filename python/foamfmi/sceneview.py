"""renderScene's picture (tutorials/bin/renderScene.py): ParaView's VTK
modules, the view of the tank (its size, axes and the camera: the tank
seen obliquely from above in 3D, from the side in 2D), the picture written
as PNG and the camera reported. Runs under ParaView's pvbatch.
"""

import math

from foamfmi.scene import fail


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


def cross(a, b):
    return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2],
            a[0]*b[1] - a[1]*b[0]]


def unit(a):
    norm = math.sqrt(sum(v*v for v in a))
    return [v/norm for v in a]


def axis(i):
    return [1.0 if j == i else 0.0 for j in range(3)]


class SceneView:
    """The camera and the picture of a Scene (foamfmi.scenedraw): its
    renderer, window, up direction, 2D flag and bounds."""

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

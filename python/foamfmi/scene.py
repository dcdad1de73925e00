"""What tutorials/bin/renderScene draws from a case, read without
ParaView: its dictionaries (the boundary, the moving patches, gravity's
direction) and the mooring lines the fmuConnector restraints wrote
(VTK/fmuConnectors/ series, or the shape columns of their
postProcessing/fmuConnectors rows). The lines become VTK polydata only
when drawn (vtkmodules imported then). Errors end the program with
'renderScene: ...'.
"""

import json
import math
import os
import re
import sys

from foamfmi import dictionary, postprocessing


def fail(message):
    sys.stderr.write("renderScene: %s\n" % message)
    sys.exit(1)


# ---------------------------------------------------- the case's dictionaries

def read_dict_text(path):
    """OpenFOAM dictionary text without comments ('' when absent)."""
    return dictionary.read_text(path, missing_ok=True)


def read_boundary(case):
    """[(name, type, nFaces)] of constant/polyMesh/boundary."""
    for path in (os.path.join(case, "constant/polyMesh/boundary"),
                 os.path.join(case, "processor0/constant/polyMesh/boundary")):
        text = read_dict_text(path)
        if text:
            break
    else:
        fail("%s: no constant/polyMesh/boundary: not a meshed OpenFOAM case"
             % case)
    return dictionary.boundary_patches(text)


def moving_patch_names(trees):
    """Patch names (or quoted regular expressions) the mesh motion moves:
    every `patches` list of constant/dynamicMeshDict and the
    sixDoFRigidBodyDisplacement patches of pointDisplacement (trees: the
    case's dictionaries as OpenFOAM reads them,
    connectorscene.read_dictionaries)."""
    names = []

    def walk(tree, in_field):
        for key, value in tree.items():
            if isinstance(value, dict):
                if in_field and value.get("type") == ["sixDoFRigidBodyDisplacement"]:
                    names.append(key)
                walk(value, in_field)
            elif key == "patches" and not in_field:
                names.extend(t for t in value if t not in "()")

    for name, tree in trees.items():
        walk(tree, name.endswith("pointDisplacement"))
    return names


def select_patches(patterns, patches, option):
    """The non-empty patches matching the names/regular expressions."""
    chosen = []
    for pattern in patterns:
        regex = pattern.strip('"')
        found = [p[0] for p in patches
                 if re.fullmatch(regex, p[0]) and p[2] > 0]
        if not found and option:
            fail("%s: no patch with faces matches '%s'; patches: %s"
                 % (option, pattern, " ".join(p[0] for p in patches)))
        chosen += [name for name in found if name not in chosen]
    return chosen


def up_direction(case):
    """Unit vector against gravity (constant/g), z by default."""
    try:
        g = dictionary.read_vector(os.path.join(case, "constant/g"), "value")
    except (OSError, dictionary.DictionaryError):
        return [0.0, 0.0, 1.0]
    norm = math.sqrt(sum(v*v for v in g))
    if len(g) == 3 and norm > 0:
        return [-v/norm for v in g]
    return [0.0, 0.0, 1.0]


# ------------------------------------------------------------ mooring lines

def near(a, b):
    return abs(a - b) <= 1e-6*max(1.0, abs(a), abs(b))


class VtkLines:
    """Connector lines written by the bridge: VTK/fmuConnectors/*.vtk.series."""

    def __init__(self, folder):
        self.series = {}
        for entry in sorted(os.listdir(folder)):
            if not entry.endswith(".vtk.series"):
                continue
            path = os.path.join(folder, entry)
            try:
                with open(path) as f:
                    files = json.load(f)["files"]
                self.series[entry[:-len(".vtk.series")]] = [
                    (float(item["time"]), os.path.join(folder, item["name"]))
                    for item in files]
            except (OSError, ValueError, KeyError, TypeError) as error:
                fail("%s: not a ParaView series file (JSON with 'files', each"
                     " with 'name' and 'time'): %s" % (path, error))

    def names(self):
        return list(self.series)

    def polydata(self, name, time):
        from vtkmodules.vtkIOLegacy import vtkPolyDataReader
        for t, path in self.series[name]:
            if near(t, time):
                reader = vtkPolyDataReader()
                reader.SetFileName(path)
                reader.ReadAllScalarsOn()   # tension and section
                reader.Update()
                if reader.GetOutput().GetNumberOfPoints() < 2:
                    fail("%s: no line in it (legacy VTK polydata with at"
                         " least 2 POINTS expected)" % path)
                return reader.GetOutput()
        return None


class DatLines:
    """Line shapes from the connector outputs, postProcessing/fmuConnectors/
    <startTime>/<name>.dat (columns shape.x[i], shape.y[i], shape.z[i])."""

    def __init__(self, folder):
        self.tables = {}   # name -> [(startTime, rows, columns of x, y, z)]
        for start in os.listdir(folder):
            try:
                start_time = float(start)
            except ValueError:
                continue
            for entry in os.listdir(os.path.join(folder, start)):
                if entry.endswith(".dat"):
                    self._read(os.path.join(folder, start, entry),
                               entry[:-4], start_time)
        for tables in self.tables.values():
            tables.sort(key=lambda table: table[0])

    def _read(self, path, name, start_time):
        try:
            header, rows = postprocessing.read_named_table(path)
        except postprocessing.PostProcessingError as error:
            fail(str(error))
        xyz = []
        for i in range(1, len(header) + 1):
            cols = ["shape.%s[%d]" % (c, i) for c in "xyz"]
            if not all(c in header for c in cols):
                break
            xyz.append([header.index(c) for c in cols])
        if len(xyz) >= 2 and rows:
            self.tables.setdefault(name, []).append((start_time, rows, xyz))

    def names(self):
        return sorted(self.tables)

    def polydata(self, name, time):
        """The shape in the row at `time`, from the latest start before it."""
        tables = [t for t in self.tables[name] if t[0] <= time + 1e-9]
        if not tables:
            return None
        _, rows, xyz = tables[-1]
        row = min(rows, key=lambda r: abs(r[0] - time))
        spacing = min((abs(r[0] - row[0]) for r in rows if r is not row),
                      default=0.0)
        if not (near(row[0], time) or abs(row[0] - time) <= 0.5*spacing):
            return None
        return polyline([[row[i] for i in cols] for cols in xyz])


def polyline(points):
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    pts, cells = vtkPoints(), vtkCellArray()
    cells.InsertNextCell(len(points))
    for i, p in enumerate(points):
        pts.InsertNextPoint(p)
        cells.InsertCellPoint(i)
    data = vtkPolyData()
    data.SetPoints(pts)
    data.SetLines(cells)
    return data


class ConnectorLines:
    """The lines' shapes from the VTK files where they have the time, else
    from the .dat files (the VTK files start at the first write time)."""

    def __init__(self, case):
        vtk_folder = os.path.join(case, "VTK/fmuConnectors")
        dat_folder = os.path.join(case, "postProcessing/fmuConnectors")
        self.sources = []
        if os.path.isdir(vtk_folder):
            self.sources.append(VtkLines(vtk_folder))
        if os.path.isdir(dat_folder):
            self.sources.append(DatLines(dat_folder))

    def names(self):
        return sorted(set(n for s in self.sources for n in s.names()))

    def polydata(self, name, time):
        for source in self.sources:
            if name in source.names():
                shape = source.polydata(name, time)
                if shape is not None:
                    return shape
        return None


def connector_lines(case, wanted):
    """The lines of the case and the names of those to draw."""
    lines = ConnectorLines(case)
    names = lines.names()
    if wanted is None:
        return lines, names
    for name in wanted:
        if name not in names:
            fail("-lines: no connector line '%s' in the case; lines: %s"
                 % (name, " ".join(names) or "none"))
    return lines, wanted

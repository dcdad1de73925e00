"""The springs, dampers and hinges of a case as tutorials/bin/renderScene
draws them, read without ParaView.

The connectors are the fmuConnector restraints of constant/dynamicMeshDict
(rigidBodyMotion: `restraints` of the motion solver's coefficients) and of
the sixDoFRigidBodyDisplacement patches of 0.orig/ (or 0/) pointDisplacement;
their kind is the FMU's model (linearSpring: spring, linearDamper: damper,
hinge: hinge, catenary and mooringLine: line, drawn from their shape
outputs by foamfmi.scene, any other: connector). Their outputs
(postProcessing/fmuConnectors/<startTime>/<name>.dat: loads, length,
tension) hold no positions, so the attachment points are placed here:

    P = c_A + R_A A.p        Q = c_B + R_B B.p  (B.p itself without bodyB)
    hinge axis = R_A A.axis

with A.p, B.p (body frames, from the body frame origin or sixDoF centre of
rotation) from the restraint's `parameters`, and a body's origin c and
rotation R at a time from postProcessing/rigidBodyMotion/<body>.dat where
the case has it (the bodies' motion at every step, that
rigidBodyMotionFromLog takes from the solver log; the rotation vector's
columns, degrees), else from the state OpenFOAM wrote at that time
(foamfmi.bodystate: the joints' q of rigidBodyMotion, the centre of
rotation and orientation of sixDoF); before the first row or written state
(at t = 0) from the body's initial placement (`transform`,
centreOfRotation/centreOfMass and orientation of a sixDoF patch, or the
initial centre of rotation of a sixDoFRigidBodyMotion solver).

The dictionaries are read as OpenFOAM reads them (foamDictionary -expand:
#include, $macros, #eval and #calc done by OpenFOAM).
"""

import math
import os
import re
import zipfile

from foamfmi import bodystate, foamdict
from foamfmi.dictionary import DictionaryError
from foamfmi.restraintmap import sixdof_frame

KINDS = {"linearSpring": "spring", "linearDamper": "damper", "hinge": "hinge",
         "catenary": "line", "mooringLine": "line"}
ORDER = ("spring", "damper", "hinge", "connector")


class Connector:
    """One restraint: name, kind, bodies (body_b None: the fixed world),
    attachment points p_a, p_b and hinge axis (body frames)."""

    def __init__(self, name, kind, body_a, body_b, p_a, p_b, axis):
        self.name, self.kind = name, kind
        self.body_a, self.body_b = body_a, body_b
        self.p_a, self.p_b, self.axis = p_a, p_b, axis


def fmu_model(path, case):
    """The FMU's modelIdentifier (its modelDescription.xml), else its file
    name without .fmu."""
    path = path.strip('"')
    for tag in ("<constant>", "<case>", "<system>"):
        if path.startswith(tag):
            folder = tag.strip("<>")
            path = os.path.join(case, "" if folder == "case" else folder,
                                path[len(tag):].lstrip("/"))
    try:
        with zipfile.ZipFile(path) as fmu:
            xml = fmu.read("modelDescription.xml").decode("utf-8", "replace")
        m = re.search(r'<CoSimulation[^>]*\bmodelIdentifier="([^"]+)"', xml)
        if m:
            return m.group(1)
    except (OSError, KeyError, zipfile.BadZipFile):
        pass
    return os.path.basename(path)[:-4] if path.endswith(".fmu") \
        else os.path.basename(path)


def _restraints(tree):
    """(name, dictionary) of the fmuConnector entries of every `restraints`
    dictionary in tree."""
    found = []
    for key, value in tree.items():
        if not isinstance(value, dict):
            continue
        if key == "restraints":
            for name, entry in value.items():
                if isinstance(entry, dict) and "fmuConnector" in (
                        entry.get("type", []) + entry.get("sixDoFRigidBodyMotionRestraint", [])):
                    found.append((name, entry))
        else:
            found += _restraints(value)
    return found


def _placements(tree, sixdof, where=""):
    """{body: (origin, rotation rows)} of the bodies' initial placement."""
    found = {}
    for key, value in tree.items():
        if not isinstance(value, dict):
            continue
        if not sixdof and "patches" in value and "momentOfInertia" in value:
            # A sixDoFRigidBodyMotion solver: its body is its first patch
            patches = [t.strip('"') for t in value["patches"] if t not in "()"]
            if patches:
                centre, rows, _ = sixdof_frame(value, where)
                found[patches[0]] = (list(centre), [list(r) for r in rows])
        elif sixdof and value.get("type") == ["sixDoFRigidBodyDisplacement"]:
            centre = value.get("centreOfRotation", value.get("centreOfMass"))
            rotation = value.get("orientation")
            if centre:
                R = foamdict.vector(rotation) if rotation else [1, 0, 0, 0, 1, 0, 0, 0, 1]
                found[key] = (foamdict.vector(centre), [R[0:3], R[3:6], R[6:9]])
        elif not sixdof and "transform" in value and value.get("parent", ["root"]) == ["root"]:
            numbers = foamdict.vector(value["transform"])
            if len(numbers) == 12:
                E = numbers[:9]   # global to body: R is its transpose
                found[key] = (numbers[9:], [E[0::3], E[1::3], E[2::3]])
        else:
            found.update(_placements(value, sixdof))
    return found


def read_dictionaries(case):
    """{name: tree} of the case's constant/dynamicMeshDict and its first
    0.orig/ or 0/pointDisplacement, as OpenFOAM reads them (foamdict.expanded,
    every digit); DictionaryError for one that cannot be read."""
    names = ["constant/dynamicMeshDict"]
    for folder in ("0.orig", "0"):
        if os.path.isfile(os.path.join(case, folder, "pointDisplacement")):
            names.append(folder + "/pointDisplacement")
            break
    return {name: foamdict.expanded(case, name, precision=17) for name in names
            if os.path.isfile(os.path.join(case, name))}


def read_connectors(case, trees=None):
    """The connectors of the case and the bodies' initial placements
    (trees: read_dictionaries' of the case, read here if None);
    DictionaryError for a dictionary that cannot be read."""
    connectors, placements = {}, {}
    if trees is None:
        trees = read_dictionaries(case)
    for name, tree in trees.items():
        sixdof = name.endswith("pointDisplacement")
        placements.update(_placements(tree, sixdof, name))
        for name, entry in _restraints(tree):
            if name in connectors:
                continue          # sixDoF: the same restraint in both bodies
            parameters = entry.get("parameters", {})
            get = lambda key: foamdict.vector(parameters[key]) if key in parameters else None
            model = fmu_model(foamdict.word(entry["fmu"]), case) if "fmu" in entry else ""
            connectors[name] = Connector(
                name, KINDS.get(model, "connector"), foamdict.word(entry["body"]),
                foamdict.word(entry["bodyB"]) if "bodyB" in entry else None,
                get("A.p") or [0.0, 0.0, 0.0], get("B.p") or [0.0, 0.0, 0.0],
                get("A.axis"))
    return [connectors[n] for n in sorted(connectors)], placements


def rotation_matrix(vector_deg):
    """Rows of the rotation by the rotation vector (degrees: angle times
    unit axis), Rodrigues' formula."""
    w = [math.radians(v) for v in vector_deg]
    angle = math.sqrt(sum(v*v for v in w))
    if angle < 1e-15:
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    k = [v/angle for v in w]
    c, s = math.cos(angle), math.sin(angle)
    return [[(c if i == j else 0.0) + k[i]*k[j]*(1 - c) + s*_levi(i, j, k)
             for j in range(3)]
            for i in range(3)]


def _levi(i, j, k):
    """(K)_ij of the cross-product matrix of k."""
    if i == j:
        return 0.0
    m = 3 - i - j
    sign = 1.0 if (i, j) in ((1, 0), (2, 1), (0, 2)) else -1.0
    return sign*k[m]


def apply(pose, point):
    centre, R = pose
    return [centre[i] + sum(R[i][j]*point[j] for j in range(3)) for i in range(3)]


class BodyMotion:
    """Bodies' origins and rotations in time from
    postProcessing/rigidBodyMotion/<body>.dat (columns time, origin,
    angle, rotation vector in degrees), else from the state written at
    the time (bodystate.written_poses; dynamic_mesh_dict: the case's
    constant/dynamicMeshDict as read_dictionaries reads it)."""

    def __init__(self, case, placements, dynamic_mesh_dict=None):
        self.case, self.tree = case, dynamic_mesh_dict or {}
        self.folder = os.path.join(case, "postProcessing/rigidBodyMotion")
        self.placements, self.rows, self.written = placements, {}, {}

    def _rows(self, body):
        if body not in self.rows:
            rows = []
            path = os.path.join(self.folder, body + ".dat")
            if os.path.isfile(path):
                with open(path) as f:
                    for line in f:
                        values = line.split()
                        if line.startswith("#") or len(values) < 8:
                            continue
                        try:
                            rows.append([float(v) for v in values[:8]])
                        except ValueError:
                            continue
            self.rows[body] = rows
        return self.rows[body]

    def has_rows(self, body):
        return bool(self._rows(body))

    def _written(self, time):
        """{body: pose} of the state written at time ({} where none is)."""
        for name in os.listdir(self.case):
            try:
                t = float(name)
            except ValueError:
                continue
            if abs(t - time) <= 1e-9*max(1.0, abs(time)):
                if name not in self.written:
                    self.written[name] = bodystate.written_poses(self.case, name, self.tree)
                return self.written[name]
        return {}

    def has_motion(self, body, times):
        """Whether the body's place is known at every one of times: rows,
        or a state written at each time after the start."""
        return self.has_rows(body) or all(
            t <= 1e-9 or body in self._written(t) for t in times)

    def pose(self, body, time):
        """(origin, rotation rows) of the body at time; None when unknown."""
        rows = self._rows(body)
        if rows:
            row = min(rows, key=lambda r: abs(r[0] - time))
            spacing = (rows[1][0] - rows[0][0]) if len(rows) > 1 else rows[0][0]
            if abs(row[0] - time) <= 0.5*abs(spacing) + 1e-9*max(1.0, abs(time)):
                return row[1:4], rotation_matrix(row[5:8])
            if time >= rows[0][0]:
                return None
        elif time > 1e-9:
            # No table of the motion: the state written at the time
            pose = self._written(time).get(body)
            return (list(pose[0]), [list(r) for r in pose[1]]) if pose else None
        return self.placements.get(body)


def positions(connector, motion, time):
    """(P, Q, hinge axis or None) in the global frame at time; None when a
    body's motion is not known then."""
    pose_a = motion.pose(connector.body_a, time)
    if pose_a is None:
        return None
    P = apply(pose_a, connector.p_a)
    if connector.body_b is None:
        Q = list(connector.p_b)
    else:
        pose_b = motion.pose(connector.body_b, time)
        if pose_b is None:
            return None
        Q = apply(pose_b, connector.p_b)
    axis = None
    if connector.axis is not None:
        axis = apply(([0.0, 0.0, 0.0], pose_a[1]), connector.axis)
    return P, Q, axis


# ------------------------------------------------------------ shapes

def _sub(a, b):
    return [x - y for x, y in zip(a, b)]


def _unit(a):
    n = math.sqrt(sum(x*x for x in a))
    return [x/n for x in a] if n > 0 else None


def _cross(a, b):
    return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0]]


def coil(P, Q, radius, turns=6, flat_normal=None, per_turn=16):
    """Points of a coil spring from P to Q: straight ends of an eighth of
    the length, a helix of `turns` turns between; with flat_normal a zig-zag
    in the plane across it (a 2D side view)."""
    d = _sub(Q, P)
    e = _unit(d)
    if e is None:
        return [P, Q]
    helper = [1.0, 0.0, 0.0] if abs(e[0]) < 0.9 else [0.0, 1.0, 0.0]
    if flat_normal is not None:
        u = _unit(_cross(flat_normal, e)) or _unit(_cross(helper, e))
        v = [0.0, 0.0, 0.0]
    else:
        u = _unit(_cross(helper, e))
        v = _cross(e, u)
    points = [list(P)]
    n = turns*per_turn
    for i in range(n + 1):
        s = 0.125 + 0.75*i/n
        phase = 2*math.pi*i/per_turn
        points.append([P[k] + s*d[k]
                       + radius*(math.sin(phase)*u[k] - math.cos(phase)*v[k])
                       for k in range(3)])
    points.append(list(Q))
    return points


def damper(P, Q):
    """(cylinder, rod) segments of a damper: the cylinder on A's side,
    over 55 % of the length, the rod from its end to Q."""
    M = [p + 0.55*(q - p) for p, q in zip(P, Q)]
    R = [p + 0.45*(q - p) for p, q in zip(P, Q)]
    return [P, M], [R, Q]


def hinge(P, Q, axis, length):
    """The hinge's cylinder: `length` along the axis through the middle of
    the two hinge points."""
    centre = [(p + q)/2 for p, q in zip(P, Q)]
    a = _unit(axis) if axis else None
    if a is None:
        a = [0.0, 1.0, 0.0]
    return [[c - 0.5*length*x for c, x in zip(centre, a)],
            [c + 0.5*length*x for c, x in zip(centre, a)]]

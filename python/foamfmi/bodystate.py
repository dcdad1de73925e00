"""The bodies' placement at a written time, from the state OpenFOAM writes
there, in either framework: what tutorials/bin/renderScene places the
connectors by when the case has no table of the bodies' motion.

    poses = written_poses(case, "1.5", trees)   # {body: (origin, rotation rows)}

A pose is the body frame's origin in global coordinates and the rotation
body to global (rows). trees: the case's dictionaries as OpenFOAM reads
them (foamdict.expanded), {"constant/dynamicMeshDict": ..., "pointDisplacement":
...}.

rigidBodyMotion: <time>/uniform/rigidBodyMotionState holds the joints'
coordinates q; each body is placed as OpenFOAM's rigidBodyModel places it
(src/rigidBodyDynamics, the same in v1912 and v2312):

    X0(body) = XJ(q) & XT & X0(parent)        X0(root) = identity

with XT the body's `transform`, XJ its joint's transform and & the spatial
transforms' product, (E1, r1) & (E2, r2) = (E1 E2, r2 + E2^T r1) (E: parent
to child, r: the child's origin in the parent's frame). A composite joint
(and `floating`, Pxyz then Rzyx) is a chain of massless bodies, one a
joint, the first with XT; a body with `mergeWith` sits at its XT from its
master. The origin is r of X0, the rotation body to global E^T.

sixDoF: each sixDoFRigidBodyDisplacement patch writes its motion's
centreOfRotation and orientation (body to global) into
<time>/pointDisplacement; a sixDoFRigidBodyMotion solver into
<time>/uniform/sixDoFRigidBodyMotionState, its body being the first of its
`patches`.
"""

import math
import os

from foamfmi import foamdict
from foamfmi.dictionary import DictionaryError

IDENTITY = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
ZERO = (0.0, 0.0, 0.0)


# --- Spatial transforms (E, r), as OpenFOAM's spatialTransform ----------------

def _matmul(a, b):
    return tuple(tuple(sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3))
                 for i in range(3))


def _transpose_times(e, v):
    """E^T v (OpenFOAM's v & E)."""
    return tuple(sum(e[k][j] * v[k] for k in range(3)) for j in range(3))


def compose(x1, x2):
    """x1 & x2."""
    (e1, r1), (e2, r2) = x1, x2
    return _matmul(e1, e2), tuple(a + b for a, b in zip(r2, _transpose_times(e2, r1)))


def _rx(a):
    c, s = math.cos(a), math.sin(a)
    return ((1.0, 0.0, 0.0), (0.0, c, s), (0.0, -s, c))


def _ry(a):
    c, s = math.cos(a), math.sin(a)
    return ((c, 0.0, -s), (0.0, 1.0, 0.0), (s, 0.0, c))


def _rz(a):
    c, s = math.cos(a), math.sin(a)
    return ((c, s, 0.0), (-s, c, 0.0), (0.0, 0.0, 1.0))


def _ra(axis, a):
    """OpenFOAM's Ra(axis, angle) (transform.H): the transpose of the
    rotation by angle about axis."""
    n = math.sqrt(sum(v * v for v in axis))
    x, y, z = (v / n for v in axis)
    c, s = math.cos(a), math.sin(a)
    t = 1.0 - c
    return ((t*x*x + c, t*x*y + s*z, t*x*z - s*y),
            (t*x*y - s*z, t*y*y + c, t*y*z + s*x),
            (t*x*z + s*y, t*y*z - s*x, t*z*z + c))


def _rs(v):
    """The transpose of the unit quaternion's rotation (joints::Rs), its
    vector part v, w = sqrt(1 - |v|^2)."""
    x, y, z = v
    w = math.sqrt(max(0.0, 1.0 - (x*x + y*y + z*z)))
    R = ((w*w + x*x - y*y - z*z, 2*(x*y - w*z), 2*(x*z + w*y)),
         (2*(x*y + w*z), w*w - x*x + y*y - z*z, 2*(y*z - w*x)),
         (2*(x*z - w*y), 2*(y*z + w*x), w*w - x*x - y*y + z*z))
    return tuple(tuple(R[j][i] for j in range(3)) for i in range(3))


def _euler(order, q):
    """E of the Euler-angle joints Rxyz, Rzyx, Ryxz: q[i] the angle about
    the i-th axis of the name, the first acting first (Rzyx: E = Rx(q[2])
    Ry(q[1]) Rz(q[0]))."""
    single = {"x": _rx, "y": _ry, "z": _rz}
    e = IDENTITY
    for axis, angle in zip(order, q):
        e = _matmul(single[axis](angle), e)
    return e


# Degrees of freedom and transform of each simple joint type
_AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}


def _simple_joint(joint):
    """(number of coordinates, function q -> (E, r)) of a joint that is not
    composite."""
    kind = foamdict.word(joint.get("type", ["null"]))
    if kind in ("Px", "Py", "Pz"):
        a = _AXES[kind[1]]
        return 1, lambda q: (IDENTITY, tuple(q[0] * v for v in a))
    if kind == "Pa":
        axis = foamdict.vector(joint["axis"])
        n = math.sqrt(sum(v * v for v in axis))
        return 1, lambda q: (IDENTITY, tuple(q[0] * v / n for v in axis))
    if kind == "Pxyz":
        return 3, lambda q: (IDENTITY, tuple(q[:3]))
    if kind in ("Rx", "Ry", "Rz"):
        single = {"Rx": _rx, "Ry": _ry, "Rz": _rz}[kind]
        return 1, lambda q: (single(q[0]), ZERO)
    if kind == "Ra":
        axis = foamdict.vector(joint["axis"])
        return 1, lambda q: (_ra(axis, q[0]), ZERO)
    if kind in ("Rxyz", "Rzyx", "Ryxz"):
        return 3, lambda q: (_euler(kind[1:], q[:3]), ZERO)
    if kind == "Rs":
        return 3, lambda q: (_rs(q[:3]), ZERO)
    if kind == "null":
        return 0, lambda q: (IDENTITY, ZERO)
    raise DictionaryError("joint type %s: not one of OpenFOAM's rigid-body joints" % kind)


def _joint_chain(joint):
    """The simple joints a joint stands for, in order."""
    kind = foamdict.word(joint.get("type", ["null"]))
    if kind == "floating":
        return [_simple_joint({"type": ["Pxyz"]}), _simple_joint({"type": ["Rzyx"]})]
    if kind == "composite":
        return [_simple_joint(j) for j in _joint_list(joint.get("joints", []))]
    return [_simple_joint(joint)]


def _joint_list(tokens):
    """The sub-dictionaries of a composite joint's `joints` list: foamdict
    keeps a list of dictionaries as its tokens, parsed here."""
    if isinstance(tokens, list) and tokens and isinstance(tokens[0], dict):
        return tokens
    joints, i = [], 0
    while i < len(tokens):
        if tokens[i] == "{":
            depth, j = 1, i + 1
            while depth:
                depth += {"{": 1, "}": -1}.get(tokens[j], 0)
                j += 1
            entry = {}
            inner = tokens[i + 1:j - 1]
            k = 0
            while k < len(inner):
                key, values = inner[k], []
                k += 1
                while k < len(inner) and inner[k] != ";":
                    values.append(inner[k])
                    k += 1
                entry[key] = values
                k += 1
            joints.append(entry)
            i = j
        else:
            i += 1
    return joints


def _transform(body):
    numbers = foamdict.vector(body["transform"]) if "transform" in body else []
    if len(numbers) != 12:
        return IDENTITY, ZERO
    e = numbers[:9]
    return (tuple(e[0:3]), tuple(e[3:6]), tuple(e[6:9])), tuple(numbers[9:])


def rigid_body_poses(coeffs, q):
    """{body: (origin, rotation rows body to global)} of a rigidBodyMotion
    model (coeffs: the dictionary holding `bodies`) at joint coordinates q.
    DictionaryError when q does not match the joints."""
    bodies = coeffs.get("bodies", {})
    x0 = {"root": (IDENTITY, ZERO)}
    used = 0
    for name, body in bodies.items():
        if not isinstance(body, dict):
            continue
        if "mergeWith" in body:
            master = foamdict.word(body["mergeWith"])
            if master not in x0:
                raise DictionaryError("body %s: mergeWith %s, no body before it" % (name, master))
            x0[name] = compose(_transform(body), x0[master])
            continue
        parent = foamdict.word(body.get("parent", ["root"]))
        if parent not in x0:
            raise DictionaryError("body %s: parent %s, no body before it" % (name, parent))
        x = x0[parent]
        for n, (dof, jcalc) in enumerate(_joint_chain(body.get("joint", {}))):
            if used + dof > len(q):
                raise DictionaryError("the state's q holds %d coordinates, the joints more"
                                      % len(q))
            xt = _transform(body) if n == 0 else (IDENTITY, ZERO)
            x = compose(compose(jcalc(q[used:used + dof]), xt), x)
            used += dof
        x0[name] = x
    if used != len(q):
        raise DictionaryError("the state's q holds %d coordinates, the joints %d"
                              % (len(q), used))
    del x0["root"]
    return {name: (r, tuple(tuple(e[j][i] for j in range(3)) for i in range(3)))
            for name, (e, r) in x0.items()}


# --- The written state ---------------------------------------------------------

def _rigid_body_coeffs(tree):
    """The dictionary of a rigidBodyMotion model (the one holding `bodies`
    and `solver`) in tree, or None."""
    if "bodies" in tree and isinstance(tree["bodies"], dict):
        return tree
    for value in tree.values():
        if isinstance(value, dict):
            found = _rigid_body_coeffs(value)
            if found is not None:
                return found
    return None


def _sixdof_solver_body(tree):
    """The body of a sixDoFRigidBodyMotion motion solver (the first of its
    `patches`), or None."""
    for key, value in tree.items():
        if isinstance(value, dict):
            if "patches" in value and "momentOfInertia" in value:
                patches = [t for t in value["patches"] if t not in "()"]
                return patches[0].strip('"') if patches else None
            found = _sixdof_solver_body(value)
            if found:
                return found
    return None


def _rows(numbers):
    return tuple(tuple(numbers[i:i + 3]) for i in (0, 3, 6))


def written_poses(case, time_name, dynamic_mesh_dict):
    """{body: (origin, rotation rows)} of the bodies whose state the
    written time time_name holds (dynamic_mesh_dict: constant/dynamicMeshDict
    as OpenFOAM reads it, or {}). DictionaryError for a state file that
    cannot be read."""
    folder = os.path.join(case, time_name)
    poses = {}
    state = os.path.join(folder, "uniform", "rigidBodyMotionState")
    coeffs = _rigid_body_coeffs(dynamic_mesh_dict)
    if coeffs is not None and os.path.isfile(state):
        q = foamdict.vector(foamdict.parse(state, case).get("q", []))
        # "q 1 ( -0.19 )": a list written with its size first
        if q and len(q) == int(q[0]) + 1:
            q = q[1:]
        poses.update(rigid_body_poses(coeffs, q))
    state = os.path.join(folder, "uniform", "sixDoFRigidBodyMotionState")
    body = _sixdof_solver_body(dynamic_mesh_dict)
    if body and os.path.isfile(state):
        d = foamdict.parse(state, case)
        if "centreOfRotation" in d and "orientation" in d:
            poses[body] = (tuple(foamdict.vector(d["centreOfRotation"])),
                           _rows(foamdict.vector(d["orientation"])))
    displacement = os.path.join(folder, "pointDisplacement")
    if os.path.isfile(displacement):
        fields = foamdict.parse(displacement, case).get("boundaryField", {})
        for patch, entry in fields.items():
            if (isinstance(entry, dict) and entry.get("type") == ["sixDoFRigidBodyDisplacement"]
                    and "centreOfRotation" in entry and "orientation" in entry):
                poses[patch] = (tuple(foamdict.vector(entry["centreOfRotation"])),
                                _rows(foamdict.vector(entry["orientation"])))
    return poses

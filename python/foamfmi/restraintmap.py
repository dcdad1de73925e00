"""OpenFOAM's built-in restraints as fmuConnector restraints with the same
physics: which FMU, which parameters, and the attachment points in the
frames the fmuConnector restraint uses.

rigidBodyMotion (src/rigidBodyDynamics/restraints) gives its points in the
fmuConnector's frames already: `refAttachmentPt` in the body's frame from
the origin its `transform` sets, `anchor` in the global frame; they become
`A.p` and `B.p` unchanged.

sixDoFRigidBodyMotion (src/sixDoFRigidBodyMotion/sixDoFRigidBodyMotion/
restraints) gives `refAttachmentPt` as a global point at the start, moved
with the body by motion.transform():
    x = centreOfRotation + Q initialQ^T (refAttachmentPt - initialCentreOfRotation)
while the fmuConnector restraint's body frame is orientation() (Q) with its
origin at the centre of rotation, so
    A.p = initialQ^T (refAttachmentPt - initialCentreOfRotation)
initialCentreOfRotation is what the sixDoFRigidBodyMotion constructor makes
it (v1912 and v2312 alike): initialCentreOfMass (default centreOfMass),
then each constraint of type point, line or plane, in their order, sets it
to its own centreOfRotation (default initialCentreOfMass); initialQ is
initialOrientation (default orientation, default the identity).

Every mapping returns a Conversion, or None for a restraint type that has
no twin (the reason in LEFT_OUT).
"""

import os
import re
from dataclasses import dataclass, field

from foamfmi.dictionary import DictionaryError
from foamfmi.foamdict import vector, word

# Built-in restraints that are not converted, and why (docs/convert.md)
LEFT_OUT = {
    "prescribedRotation": "it drives the body's rotation to a prescribed "
                          "function of time, it connects nothing",
    "externalForce": "a force given as a function of time, it connects nothing",
    "softWall": "a contact with a plane, not a connector law of the project",
    "linearSpringDamper": "its anchor is a function of time and its force is relaxed "
                          "against its previous evaluation: not a connector law",
}


# Built-in restraints of rigidBodyMotion alone that are not converted
RIGID_LEFT_OUT = {
    "linearAxialAngularSpring": "OpenFOAM's rigidBodyMotion version turns the body away "
                                "from its reference orientation (it takes the body's "
                                "global-to-body rotation for body-to-global): no twin "
                                "(docs/convert.md)",
}


@dataclass
class Conversion:
    """An fmuConnector restraint: its FMU (by name) and parameters, each
    value the text of an OpenFOAM entry; notes say where the physics
    differs from the built-in restraint."""
    fmu: str
    parameters: dict
    notes: list = field(default_factory=list)


def number_text(x):
    """A number to 15 significant digits (0.45 - 0.4 as 0.05)."""
    return "%.15g" % x


def vector_text(v):
    return "(%s)" % " ".join(number_text(x) for x in v)


def _entry(restraint, key, where):
    if key not in restraint:
        raise DictionaryError("%s: no entry %s" % (where, key))
    return restraint[key]


def _scalar(restraint, key, where):
    value = _entry(restraint, key, where)
    try:
        (number,) = value
        return float(number)
    except ValueError:
        raise DictionaryError("%s: entry %s is %s, expected a number"
                              % (where, key, " ".join(value))) from None


def _vector(restraint, key, where, size=3):
    value = _entry(restraint, key, where)
    try:
        numbers = vector(value)
    except DictionaryError:
        numbers = []
    if len(numbers) != size:
        raise DictionaryError("%s: entry %s is %s, expected %d numbers in ( )"
                              % (where, key, " ".join(value), size))
    return numbers


def centre_of_rotation(motion, where):
    """sixDoFRigidBodyMotion's initialCentreOfRotation of the motion
    dictionary motion (module docstring)."""
    return centre_and_source(motion, where)[0]


def centre_and_source(motion, where):
    """initialCentreOfRotation and the entry it comes from, in words."""
    key = "initialCentreOfMass" if "initialCentreOfMass" in motion else "centreOfMass"
    centre_of_mass = _vector(motion, key, where)
    centre, source = centre_of_mass, key
    constraints = motion.get("constraints", {})
    if not isinstance(constraints, dict):
        raise DictionaryError("%s: entry constraints is not a dictionary" % where)
    for name, constraint in constraints.items():
        if not isinstance(constraint, dict):
            continue
        kind = word(_entry(constraint, "sixDoFRigidBodyMotionConstraint",
                           "%s, constraint %s" % (where, name)))
        if kind in ("point", "line", "plane"):
            centre = (_vector(constraint, "centreOfRotation",
                              "%s, constraint %s" % (where, name))
                      if "centreOfRotation" in constraint else centre_of_mass)
            source = "the %s constraint %s" % (kind, name)
    return centre, source


def initial_orientation(motion, where):
    """initialQ, rows of the body-to-global tensor."""
    for key in ("initialOrientation", "orientation"):
        if key in motion:
            q = _vector(motion, key, where, size=9)
            return [q[0:3], q[3:6], q[6:9]]
    return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]


def sixdof_frame(motion, where):
    """(initialCentreOfRotation, initialQ rows, where the centre comes
    from) by the rules of OpenFOAM's constructor (module docstring)."""
    centre, source = centre_and_source(motion, where)
    return centre, initial_orientation(motion, where), source


def sixdof_attachment(point, motion, where, frame=None):
    """A.p of a sixDoF refAttachmentPt: initialQ^T (point - centre), the
    centre and initialQ those of frame (sixdof_frame, or the same taken
    from OpenFOAM) or else sixdof_frame's."""
    centre, q, _ = frame or sixdof_frame(motion, where)
    d = [p - c for p, c in zip(point, centre)]
    return [sum(q[i][j] * d[i] for i in range(3)) for j in range(3)]


def _reference_orientation(restraint, where):
    """The referenceOrientation of an angular spring as the FMU parameter's
    text (OpenFOAM's default, the identity, where it has none)."""
    orientation = (_vector(restraint, "referenceOrientation", where, size=9)
                   if "referenceOrientation" in restraint else [1, 0, 0, 0, 1, 0, 0, 0, 1])
    return vector_text(orientation)


# tabulatedAxialAngularSpring.fmu's most table points (table.angle[1..64])
TABLE_POINTS = 64

# OpenFOAM's outOfBounds, as the FMU's outOfBounds codes
OUT_OF_BOUNDS = {"error": 0, "warn": 1, "clamp": 2, "repeat": 3}


def _table_path(name, case):
    """The file name of an interpolationTable as OpenFOAM expands it, for
    the case folder case: $FOAM_CASE, <case>, <constant>, <system>; a
    relative name from the case (where the solver runs)."""
    for tag, folder in (("$FOAM_CASE", ""), ("${FOAM_CASE}", ""), ("<case>", ""),
                        ("<constant>", "constant"), ("<system>", "system")):
        if name.startswith(tag):
            name = os.path.join(case, folder, name[len(tag):].lstrip("/"))
    return name if os.path.isabs(name) else os.path.join(case, name)


def read_table(path, where):
    """The (x, y) points of an interpolationTable file of OpenFOAM's
    reader (readerType openFoam): a list of (x y) pairs."""
    try:
        with open(path) as f:
            text = f.read()
    except OSError as e:
        raise DictionaryError("%s: table file %s: %s" % (where, path, e.strerror)) from None
    text = re.sub(r"//[^\n]*|/\*.*?\*/", " ", text, flags=re.S)
    pairs = re.findall(r"\(\s*([^()\s]+)\s+([^()\s]+)\s*\)", text)
    rest = re.sub(r"\(\s*[^()\s]+\s+[^()\s]+\s*\)", " ", text).split()
    try:
        points = [(float(x), float(y)) for x, y in pairs]
    except ValueError:
        points = []
    if not points or "".join(rest) not in ("()", "%d()" % len(points)):
        raise DictionaryError("%s: table file %s is not a list of (angle moment) pairs"
                              % (where, path))
    return points


def _tabulated(restraint, where, case):
    """The FMU parameters of a sixDoF tabulatedAxialAngularSpring and the
    notes."""
    reader = word(restraint["readerType"]) if "readerType" in restraint else "openFoam"
    if reader != "openFoam":
        raise DictionaryError("%s: readerType %s: the converter reads readerType openFoam "
                              "tables only" % (where, reader))
    points = read_table(_table_path(word(_entry(restraint, "file", where)), case), where)
    if len(points) > TABLE_POINTS:
        raise DictionaryError("%s: a table of %d points, tabulatedAxialAngularSpring.fmu "
                              "takes at most %d" % (where, len(points), TABLE_POINTS))
    angle_format = word(_entry(restraint, "angleFormat", where))
    if angle_format not in ("degrees", "degree", "radians", "radian"):
        raise DictionaryError("%s: angleFormat %s, expected degrees or radians"
                              % (where, angle_format))
    bounds = word(restraint["outOfBounds"]) if "outOfBounds" in restraint else "warn"
    if bounds not in OUT_OF_BOUNDS:
        raise DictionaryError("%s: outOfBounds %s, expected one of %s"
                              % (where, bounds, ", ".join(OUT_OF_BOUNDS)))
    padding = [0.0] * (TABLE_POINTS - len(points))
    degrees = angle_format.startswith("degree")
    notes = []
    half_turn = 180.0 if degrees else 3.141592653589793
    if bounds == "warn" and not (points[0][0] <= -half_turn and points[-1][0] > half_turn):
        notes.append("outOfBounds warn: OpenFOAM warns where the angle leaves the table; "
                     "the FMU takes the end moments as it does, without the warning")
    return {
        "damping": number_text(_scalar(restraint, "damping", where)),
        "B.axis": vector_text(_vector(restraint, "axis", where)),
        "referenceOrientation": _reference_orientation(restraint, where),
        "table.points": str(len(points)),
        "table.angle": vector_text([x for x, _ in points] + padding),
        "table.moment": vector_text([y for _, y in points] + padding),
        "angleInDegrees": "1" if degrees else "0",
        "outOfBounds": str(OUT_OF_BOUNDS[bounds]),
        "A.p": "(0 0 0)",
        "B.p": "(0 0 0)",
    }, notes


def convert(kind, restraint, framework, motion, where, frame=None, case="."):
    """The Conversion of a built-in restraint of type kind (its entries in
    restraint, its motion dictionary motion; framework 'rigidBody' or
    'sixDoF'; frame: a sixDoF motion's initial centre of rotation,
    orientation and their source, default sixdof_frame's; case: the case
    folder, that table files are found from), or None when it has no
    twin."""
    if kind == "linearSpring":
        attachment = _vector(restraint, "refAttachmentPt", where)
        notes = []
        if framework == "sixDoF":
            frame = frame or sixdof_frame(motion, where)
            attachment = sixdof_attachment(attachment, motion, where, frame)
            notes.append("A.p: refAttachmentPt from the centre of rotation %s (%s), in "
                         "the body's starting orientation" % (vector_text(frame[0]), frame[2]))
        return Conversion("linearSpring", {
            "stiffness": number_text(_scalar(restraint, "stiffness", where)),
            "damping": number_text(_scalar(restraint, "damping", where)),
            "restLength": number_text(_scalar(restraint, "restLength", where)),
            "A.p": vector_text(attachment),
            "B.p": vector_text(_vector(restraint, "anchor", where)),
        }, notes)
    if kind == "linearDamper":
        # F = -coeff v at the body's reference point (rigidBodyMotion: the
        # origin of its frame; sixDoF: the centre of rotation)
        conversion = Conversion("translationalDamper", {
            "damping": number_text(_scalar(restraint, "coeff", where)),
            "A.p": "(0 0 0)",
            "B.p": "(0 0 0)",
        })
        if framework == "sixDoF":
            conversion.notes.append(
                "OpenFOAM's sixDoF linearDamper applies its force at the global "
                "origin (sixDoFRigidBodyMotion::applyRestraints leaves its "
                "position at zero), a moment centreOfRotation x (coeff v) about "
                "the centre of rotation that fmuConnector, applying the force at "
                "the centre of rotation, does not; a constraint on the rotation "
                "can remove it (floatingObject's axis constraint does)")
        return conversion
    if kind == "sphericalAngularSpring" and framework == "sixDoF":
        # OpenFOAM's law step by step; its moment is no gradient at finite
        # angles (connectors/sphericalAngularSpring/README.md)
        return Conversion("sphericalAngularSpring", {
            "stiffness": number_text(_scalar(restraint, "stiffness", where)),
            "damping": number_text(_scalar(restraint, "damping", where)),
            "referenceOrientation": _reference_orientation(restraint, where),
            "A.p": "(0 0 0)",
            "B.p": "(0 0 0)",
        })
    if kind == "linearAxialAngularSpring":
        if framework == "rigidBody":
            return None  # see RIGID_LEFT_OUT
        return Conversion("axialAngularSpring", {
            "stiffness": number_text(_scalar(restraint, "stiffness", where)),
            "damping": number_text(_scalar(restraint, "damping", where)),
            "B.axis": vector_text(_vector(restraint, "axis", where)),
            "referenceOrientation": _reference_orientation(restraint, where),
            "A.p": "(0 0 0)",
            "B.p": "(0 0 0)",
        })
    if kind == "tabulatedAxialAngularSpring":
        # sixDoF only: rigidBodyMotion has no such restraint
        parameters, notes = _tabulated(restraint, where, case)
        return Conversion("tabulatedAxialAngularSpring", parameters, notes)
    if kind == "sphericalAngularDamper":
        # M = -coeff omega, a couple (both frameworks)
        return Conversion("rotationalDamper", {
            "damping": number_text(_scalar(restraint, "coeff", where)),
            "A.p": "(0 0 0)",
            "B.p": "(0 0 0)",
        })
    return None

"""foamFmiConvert [-dry-run] [-dict FILE]... [-fmu-dir DIR] CASE

Replaces each of OpenFOAM's built-in restraints in a case that a connector
FMU can do by an fmuConnector restraint with the same physics
(foamfmi.restraintmap, docs/convert.md): linearSpring by linearSpring.fmu,
linearDamper by translationalDamper.fmu, sphericalAngularDamper by
rotationalDamper.fmu, in rigidBodyMotion and in sixDoFRigidBodyMotion (the
motion solver's coefficients and the sixDoFRigidBodyDisplacement patches of
a pointDisplacement file), and sixDoF's linearAxialAngularSpring by
axialAngularSpring.fmu, tabulatedAxialAngularSpring (its table read from its
file) by tabulatedAxialAngularSpring.fmu and sphericalAngularSpring by
sphericalAngularSpring.fmu. It copies the FMUs into CASE/constant/fmu/ and
adds libfoamFmiBridge.so to the libs of system/controlDict.

The dictionaries are read by OpenFOAM's own reader (foamDictionary -expand:
#include, #eval, $macros as the solver reads them); each replaced restraint
is rewritten where it stands in the file, the rest of the file as it was.
Restraints that have no FMU twin are left as they are and listed.

  -dry-run     print what would change (a diff of every file), change nothing
  -dict FILE   a dictionary to convert, relative to CASE (repeatable);
               default: constant/dynamicMeshDict, 0/pointDisplacement and
               0.orig/pointDisplacement where they exist
  -fmu-dir DIR the FMUs to copy (default: $FOAMFMI_FMU_DIR, else the
               project's build/fmus)
"""

import difflib
import os
import re
import shutil
import sys

from foamfmi import cli, foamdict
from foamfmi.dictionary import DictionaryError
from foamfmi.dictspan import dictionary_spans, indentation
from foamfmi.restraintmap import LEFT_OUT, RIGID_LEFT_OUT, convert, sixdof_frame
from foamfmi.sixdofcentre import FrameError, openfoam_frame

# Entries of a motion state (a restart's) that make OpenFOAM's state at the
# start differ from the initial frame the restraints refer to
STATE_KEYS = ("centreOfRotation", "initialOrientation", "initialCentreOfMass")

PROG = "foamFmiConvert"
LIBRARY = "libfoamFmiBridge.so"
DEFAULT_DICTS = ("constant/dynamicMeshDict", "0/pointDisplacement", "0.orig/pointDisplacement")


class ConvertError(RuntimeError):
    """A case the converter cannot convert; the message says why."""


def expanded(case, name):
    """The dictionary file case/name as OpenFOAM reads it, parsed
    (foamdict.expanded); ConvertError when it cannot be read."""
    try:
        return foamdict.expanded(case, name)
    except DictionaryError as error:
        raise ConvertError(str(error)) from error


def restraints_of(tree, path=()):
    """(path of the restraints dictionary, its motion dictionary,
    framework) of every restraints dictionary in tree: rigidBodyMotion's
    beside 'bodies', sixDoF's beside 'mass'."""
    for key, value in tree.items():
        if not isinstance(value, dict):
            continue
        if key == "restraints" and "bodies" in tree:
            yield path + (key,), tree, "rigidBody"
        elif key == "restraints" and "mass" in tree:
            yield path + (key,), tree, "sixDoF"
        else:
            yield from restraints_of(value, path + (key,))


def motion_frame(motion, where):
    """A sixDoF motion's initial centre of rotation and orientation: as
    OpenFOAM's sixDoFRigidBodyMotion constructs them (sixDoFSim), checked
    against the constructor's rules (restraintmap.sixdof_frame); by the
    rules alone where there is no sixDoFSim or the dictionary holds a
    motion state."""
    centre, q, source = sixdof_frame(motion, where)
    if any(key in motion for key in STATE_KEYS):
        return centre, q, source + "; by OpenFOAM's rules: the dictionary holds a motion state"
    try:
        frame = openfoam_frame(motion)
    except FrameError as err:
        raise ConvertError("%s: %s" % (where, err)) from None
    if frame is None:
        return centre, q, source + "; by OpenFOAM's rules: no sixDoFSim to ask OpenFOAM"
    differ = max([abs(a - b) for a, b in zip(frame[0], centre)]
                 + [abs(a - b) for r, s in zip(frame[1], q) for a, b in zip(r, s)])
    if differ > 1e-9 * (1 + max(abs(c) for c in centre)):
        raise ConvertError("%s: OpenFOAM gives the motion the centre of rotation %s and the "
                           "orientation %s, foamFmiConvert's reading of its constructor %s "
                           "and %s (%s): the converter is wrong here, convert by hand"
                           % (where, frame[0], frame[1], centre, q, source))
    return frame[0], frame[1], source + ", as OpenFOAM's sixDoFRigidBodyMotion gives it"


def body_of(restraint, motion, path, framework, where):
    """The fmuConnector's body: a rigidBodyMotion restraint's own, or the
    name of the body a sixDoF motion moves (the point-patch condition's
    patch, the motion solver's first patch, sixDoFSim's body)."""
    if framework == "rigidBody":
        if "body" not in restraint:
            raise DictionaryError("%s: no entry body (a rigidBodyMotion restraint "
                                  "names its body)" % where)
        return foamdict.word(restraint["body"])
    if len(path) >= 3 and path[-3] in ("boundaryField", "bodies"):
        return path[-2]  # a patch; a body of sixDoFSim's constant/sixDoFBodies
    if "patches" in motion:
        patches = [p for p in motion["patches"] if p not in "()"]
        if patches:
            return patches[0].strip('"')
    raise DictionaryError("%s: no patches in the motion dictionary: "
                          "cannot name the body" % where)


def restraint_text(name, framework, body, conversion, indent):
    """The fmuConnector restraint's entry, indented as the one it replaces."""
    type_key = "type" if framework == "rigidBody" else "sixDoFRigidBodyMotionRestraint"
    width = max(len(k) for k in conversion.parameters)
    lines = [name, "{",
             "    %-12s fmuConnector;" % type_key,
             '    %-12s "<constant>/fmu/%s.fmu";' % ("fmu", conversion.fmu),
             "    %-12s %s;" % ("body", body),
             "    parameters", "    {"]
    lines += ["        %-*s %s;" % (width, k, v) for k, v in conversion.parameters.items()]
    lines += ["    }", "}"]
    return ("\n" + indent).join(lines)


def sixdof_names(trees):
    """The names of sixDoF restraints that stand in more than one motion of
    the trees (the expanded files)."""
    seen, shared = set(), set()
    for tree in trees:
        for path, _, framework in restraints_of(tree):
            if framework == "sixDoF":
                for restraint_name, _ in foamdict_items(tree, path):
                    (shared if restraint_name in seen else seen).add(restraint_name)
    return shared


def convert_file(case, name, tree, shared, report):
    """The new text of case/name (None when nothing changes) and the FMUs
    it names, by name, from tree, the file as OpenFOAM reads it; shared:
    sixDoF restraint names that more than one motion uses (sixdof_names);
    report(line) is told what is done."""
    with open(os.path.join(case, name)) as f:
        text = f.read()
    spans = None
    replacements, fmus, frames = [], set(), {}
    for path, motion, framework in restraints_of(tree):
        for restraint_name, restraint in foamdict_items(tree, path):
            type_key = "type" if framework == "rigidBody" else "sixDoFRigidBodyMotionRestraint"
            where = "%s, restraint %s" % (name, restraint_name)
            if type_key not in restraint:
                raise ConvertError("%s: no entry %s (a %s restraint names its type by it)"
                                   % (where, type_key, framework + "Motion"))
            kind = foamdict.word(restraint[type_key])
            if kind == "fmuConnector":
                continue
            frame = None
            if framework == "sixDoF" and kind == "linearSpring":
                if path not in frames:
                    frames[path] = motion_frame(motion, "%s, %s" % (name, ".".join(path[:-1])))
                frame = frames[path]
            conversion = convert(kind, restraint, framework, motion, where, frame, case)
            if conversion is None:
                reason = (RIGID_LEFT_OUT.get(kind) if framework == "rigidBody" else None) \
                    or LEFT_OUT.get(kind, "not a restraint the converter knows")
                report("%s (%s): left as it is: %s" % (where, kind, reason))
                continue
            body = body_of(restraint, motion, path, framework, where)
            if spans is None:
                spans = dictionary_spans(text, name)
            span = spans.get(path + (restraint_name,))
            if span is None:
                raise ConvertError("%s: not written in this file (an #include or a $macro "
                                   "brings it in): convert the file that holds it (-dict)"
                                   % where)
            new_name = restraint_name
            if framework == "sixDoF" and restraint_name in shared:
                # fmuConnector restraints of one name in two sixDoF motions
                # are one connector between the two bodies
                new_name = "%s_%s" % (restraint_name, body)
            replacements.append((span, restraint_text(
                new_name, framework, body, conversion, indentation(text, span[0]))))
            fmus.add(conversion.fmu)
            report("%s (%s): fmuConnector %s.fmu, body %s, %s" % (
                where, kind, conversion.fmu, body,
                ", ".join("%s %s" % kv for kv in conversion.parameters.items())))
            if new_name != restraint_name:
                report("    renamed %s: another sixDoF motion has a restraint %s, and "
                       "fmuConnector restraints of one name in two motions are one "
                       "connector between the two bodies" % (new_name, restraint_name))
            for note in conversion.notes:
                report("    note: " + note)
    if not replacements:
        return None, fmus
    for (start, end), new in sorted(replacements, reverse=True):
        text = text[:start] + new + text[end:]
    return text, fmus


def foamdict_items(tree, path):
    """The dictionary entries of the dictionary at path of tree."""
    node = tree
    for key in path:
        node = node[key]
    return [(k, v) for k, v in node.items() if isinstance(v, dict)]


def control_dict_text(case):
    """system/controlDict's new text with libfoamFmiBridge.so in its libs,
    None when it is there already."""
    name = "system/controlDict"
    tree = expanded(case, name)
    libs = [t.strip('"') for t in tree.get("libs", []) if t not in "()"]
    if LIBRARY in libs:
        return None
    with open(os.path.join(case, name)) as f:
        text = f.read()
    spans = dictionary_spans(text, name)
    entry = 'libs            (%s);' % " ".join('"%s"' % lib for lib in libs + [LIBRARY])
    if ("libs",) in spans:
        start, end = spans[("libs",)]
        return text[:start] + entry + text[end:]
    if "libs" in tree:
        raise ConvertError("%s: libs is not written in the file (an #include or a $macro "
                           "brings it in): add \"%s\" to it" % (name, LIBRARY))
    after = spans.get(("FoamFile",), (0, 0))[1]
    separator = re.match(r"[ \t]*\n(?:[ \t]*\n)*[ \t]*// \*[ *]*//[^\n]*\n", text[after:])
    if separator:
        after += separator.end()
    return text[:after] + "\n" + entry + "\n" + text[after:]


def fmu_dir_default():
    if os.environ.get("FOAMFMI_FMU_DIR"):
        return os.environ["FOAMFMI_FMU_DIR"]
    top = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    return os.path.join(top, "build", "fmus")


def run(case, dicts, fmu_dir, dry_run, out=print):
    """Convert case (module docstring); returns the number of restraints
    converted."""
    if not os.path.isdir(case):
        raise ConvertError("%s: no such case folder" % case)
    dicts = dicts or [d for d in DEFAULT_DICTS if os.path.isfile(os.path.join(case, d))]
    if not dicts:
        raise ConvertError("%s: none of %s" % (case, ", ".join(DEFAULT_DICTS)))
    for name in dicts:
        if not os.path.isfile(os.path.join(case, name)):
            raise ConvertError("%s: no such file in the case %s" % (name, case))
    trees = {name: expanded(case, name) for name in dicts}
    shared = sixdof_names(trees.values())
    changes, fmus, lines = {}, set(), []
    for name in dicts:
        text, file_fmus = convert_file(case, name, trees[name], shared, lines.append)
        if text is not None:
            changes[name] = text
            fmus |= file_fmus
    converted = sum(1 for line in lines if ": fmuConnector " in line)
    for line in lines:
        out(line)
    if not changes:
        out("%s: no built-in restraint to convert in %s" % (case, ", ".join(dicts)))
        return 0
    control = control_dict_text(case)
    if control is not None:
        changes["system/controlDict"] = control
    copies = []
    for fmu in sorted(fmus):
        source = os.path.join(fmu_dir, fmu + ".fmu")
        if not os.path.isfile(source):
            raise ConvertError("%s: no such FMU (build it: ./Allwmake; or name the "
                               "folder of the FMUs with -fmu-dir)" % source)
        copies.append((source, os.path.join("constant", "fmu", fmu + ".fmu")))
    for name, text in changes.items():
        with open(os.path.join(case, name)) as f:
            old = f.read()
        if dry_run:
            out("".join(difflib.unified_diff(old.splitlines(True), text.splitlines(True),
                                             name, name + " (converted)")).rstrip("\n"))
        else:
            with open(os.path.join(case, name), "w") as f:
                f.write(text)
            out("%s: written" % name)
    shown = "$FOAMFMI_FMU_DIR" if os.path.realpath(fmu_dir) == os.path.realpath(
        os.environ.get("FOAMFMI_FMU_DIR", "")) else fmu_dir
    for source, target in copies:
        if dry_run:
            out("would copy %s to %s" % (os.path.join(shown, os.path.basename(source)), target))
        else:
            os.makedirs(os.path.join(case, "constant", "fmu"), exist_ok=True)
            shutil.copyfile(source, os.path.join(case, target))
            out("%s: copied from %s" % (target, os.path.join(shown, os.path.basename(source))))
    return converted


def main(argv=None):
    p = cli.parser(PROG, __doc__)
    p.add_argument("-dry-run", action="store_true", help="print what would change")
    p.add_argument("-dict", action="append", default=[], metavar="FILE",
                   help="a dictionary to convert, relative to CASE")
    p.add_argument("-fmu-dir", default=None, metavar="DIR", help="the FMUs to copy")
    p.add_argument("case", metavar="CASE", help="the case folder")
    args = p.parse_args(argv)
    try:
        run(args.case, args.dict, args.fmu_dir or fmu_dir_default(), args.dry_run)
    except (ConvertError, DictionaryError, OSError) as err:
        cli.fail(PROG, str(err))


if __name__ == "__main__":
    main(sys.argv[1:])

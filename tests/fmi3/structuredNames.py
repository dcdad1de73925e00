#!/usr/bin/env python3
"""FMI 3.0 structured names: every variable is a leaf of the name tree.

Under variableNamingConvention="structured" a name is a path (a.b.c, an
element a[2] of an array a); FMI 3.0.2 allows an array variable only as a
leaf of that tree, and a scalar variable is a leaf too. This check fails on
any variable whose name is also the parent of another variable's name (the
array shape of 11 x 3 beside shape.tension, say), naming the file, the
variable and its children.

Usage:
  structuredNames.py DIR...          every FMI 3.0 modelDescription.xml in
                                     the .fmu files under the DIRs (the
                                     build), at least one, and every .fmu
                                     named by --require
  structuredNames.py --require fmi3/linearSpring.fmu,... DIR...
  structuredNames.py FILE.xml        one modelDescription.xml
Exit code 0 when every description passes, 1 otherwise.
"""
import os
import sys
import xml.etree.ElementTree as ET
import zipfile

VARIABLE_TAGS = {"Float32", "Float64", "Int8", "UInt8", "Int16", "UInt16",
                 "Int32", "UInt32", "Int64", "UInt64", "Boolean", "String",
                 "Binary", "Enumeration", "Clock"}


def problems(xml_text, where):
    """The violations in one modelDescription.xml, as messages; None when
    it is not an FMI 3.0 description with structured names."""
    root = ET.fromstring(xml_text)
    if not root.get("fmiVersion", "").startswith("3."):
        return None
    if root.get("variableNamingConvention", "flat") != "structured":
        return None
    variables = root.find("ModelVariables")
    declared = {}
    for v in variables if variables is not None else []:
        if v.tag in VARIABLE_TAGS:
            dims = [d.get("start") or "vr " + (d.get("valueReference") or "?")
                    for d in v.findall("Dimension")]
            declared[v.get("name")] = dims
    found = []
    for name, dims in declared.items():
        children = sorted(n for n in declared
                          if n.startswith(name + ".") or n.startswith(name + "["))
        if children:
            what = ("array variable %s [%s]" % (name, ",".join(dims)) if dims
                    else "scalar variable %s" % name)
            found.append("%s: %s is also the parent of %s; FMI 3.0's structured"
                         " names allow a variable (an array above all) only as"
                         " a leaf of the name hierarchy"
                         % (where, what, ", ".join(children)))
    return found


def fmus(dirs):
    for top in dirs:
        for root, _, names in os.walk(top):
            for name in sorted(names):
                if name.endswith(".fmu"):
                    yield os.path.join(root, name)


def main(args):
    required = []
    if args[:1] == ["--require"]:
        required = [r for r in args[1].split(",") if r]
        args = args[2:]
    if not args:
        print(__doc__)
        return 2
    failures, checked = [], []
    if len(args) == 1 and args[0].endswith(".xml"):
        with open(args[0], "rb") as f:
            found = problems(f.read(), args[0])
        if found is None:
            failures.append(args[0] + ": not an FMI 3.0 description with"
                            " structured names")
        else:
            failures += found
            checked.append(args[0])
    else:
        for path in fmus(args):
            try:
                with zipfile.ZipFile(path) as z:
                    text = z.read("modelDescription.xml")
                found = problems(text, path)
            except (zipfile.BadZipFile, KeyError, ET.ParseError) as e:
                # the importer's tests build broken archives on purpose
                print("not read: %s (%s)" % (path, e))
                continue
            if found is not None:
                checked.append(path)
                failures += found
        for r in required:
            if not any(c.endswith(os.sep + r) for c in checked):
                failures.append("%s: not found as an FMI 3.0 FMU with structured"
                                " names under %s" % (r, ", ".join(args)))
        if not checked:
            failures.append("no FMI 3.0 FMU with structured names under "
                            + ", ".join(args))
    for c in checked:
        print("checked " + c)
    for f in failures:
        print("FAIL " + f)
    print("%d descriptions checked, %d problems" % (len(checked), len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

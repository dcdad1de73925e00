"""OpenFOAM dictionary files as the scripts need them: an entry's value
(scalar, word, vector) found by its keyword anywhere in the file, the
patches of constant/polyMesh/boundary, the points of an ASCII
polyMesh/points file, and entries set in place.

This is a reader of flat entries by regular expression, not a parser:
a keyword is found wherever it first stands (in any sub-dictionary), and
#include, $macros and #calc are not expanded. Comments (// and /* */)
are skipped.
"""

import re


class DictionaryError(ValueError):
    """An entry that is not in a dictionary file, or not of its kind."""


def strip_comments(text):
    """text without its // and /* */ comments."""
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def read_text(path, missing_ok=False):
    """The text of the dictionary file at path without comments; '' for a
    missing or unreadable file when missing_ok, else OSError."""
    try:
        with open(path) as f:
            text = f.read()
    except OSError:
        if missing_ok:
            return ""
        raise
    return strip_comments(text)


def _search(text, pattern, key, path, flags=0):
    m = re.search(pattern, text, flags)
    if not m:
        raise DictionaryError("no %s in %s" % (key, path))
    return m


def read_scalar(path, key):
    """The number of the first 'key number;' entry of the file at path."""
    m = _search(read_text(path), r"\b" + re.escape(key) + r"\s+([-+0-9.eE]+)\s*;", key, path)
    return float(m.group(1))


def entry_text(text, key):
    """The value, as written, of the first 'key value;' entry that starts a
    line of a dictionary's text: '0.1', '(0 0 -9.81)', 'interFoam'."""
    m = re.search(r"^\s*" + re.escape(key) + r"\s+([^;]+);", text, re.M)
    if not m:
        raise DictionaryError("no %s" % key)
    return m.group(1).strip()


def read_word(path, key):
    """The word of the first 'key word;' entry that starts a line (a
    top-level entry such as application in system/controlDict)."""
    m = _search(read_text(path), r"^\s*" + re.escape(key) + r"\s+([^\s;]+)\s*;", key, path,
                re.M)
    return m.group(1)


def read_vector(path, key):
    """The numbers of the first 'key (x y z ...)' entry (value of
    constant/g, say), as floats."""
    m = _search(read_text(path), r"\b" + re.escape(key) + r"\s*\(([^)]*)\)", key, path)
    try:
        return [float(v) for v in m.group(1).split()]
    except ValueError:
        raise DictionaryError("%s in %s is not a list of numbers: (%s)"
                              % (key, path, m.group(1))) from None


def read_points(path):
    """[(x, y, z)] of the ASCII points file at path (polyMesh/points: its
    count, then one '(x y z)' a line)."""
    text = read_text(path)
    m = re.search(r"^\s*(\d+)\s*\(", text, re.M)
    if not m:
        raise DictionaryError("%s: no list of points (an ASCII polyMesh/points file)" % path)
    points = [tuple(float(v) for v in p.groups()) for p in re.finditer(
        r"\(\s*([^\s()]+)\s+([^\s()]+)\s+([^\s()]+)\s*\)", text[m.end():])]
    if len(points) != int(m.group(1)):
        raise DictionaryError("%s: %d points read, the file says %s"
                              % (path, len(points), m.group(1)))
    return points


def boundary_patches(text):
    """[(name, type, nFaces)] of the text of a constant/polyMesh/boundary
    file (comments stripped)."""
    patches = []
    for m in re.finditer(r"([A-Za-z_][\w.:-]*)\s*\{([^{}]*)\}", text):
        if m.group(1) == "FoamFile":
            continue
        kind = re.search(r"\btype\s+(\w+)\s*;", m.group(2))
        faces = re.search(r"\bnFaces\s+(\d+)\s*;", m.group(2))
        patches.append((m.group(1), kind.group(1) if kind else "",
                        int(faces.group(1)) if faces else 0))
    return patches


def substitute(path, pattern, replacement, count=1):
    """Replace the regular expression pattern (multi-line: ^ and $ match at
    each line) in the file at path; DictionaryError when it is not there."""
    with open(path) as f:
        text = f.read()
    new, n = re.subn(pattern, replacement, text, count=count, flags=re.M)
    if n == 0:
        raise DictionaryError("%s: no match for %r" % (path, pattern))
    with open(path, "w") as f:
        f.write(new)


def set_entry(path, key, value, width=0):
    """Set the top-level entry 'key ...;' of the file at path (one that
    starts a line) to 'key value;', the keyword padded to width columns
    (OpenFOAM's files use 16) or followed by one space; the entry must be
    there exactly once."""
    with open(path) as f:
        text = f.read()
    entry = (key.ljust(width) if width else key + " ") + str(value) + ";"
    new, n = re.subn(r"^" + re.escape(key) + r"\s+[^;]*;", lambda _: entry, text, flags=re.M)
    if n != 1:
        raise DictionaryError("%s: %d entries %s, expected one" % (path, n, key))
    with open(path, "w") as f:
        f.write(new)

"""OpenFOAM dictionary files parsed into nested dictionaries, for the
entries that dictionary's regular expressions cannot find: a restraint's
sub-dictionary, whose entries come from #include files and $macros.

    d = parse(path, case)        # {keyword: sub-dictionary or [tokens]}
    vector(d["parameters"]["A.p"])      # [0.1, 0.0, 0.17]

A value is the list of its tokens, without the ';' ("(0.1 0 0.17)" is
['(', '0.1', '0', '0.17', ')']). Expanded: #include, #includeIfPresent and
#sinclude (a file name relative to the including file, or starting with
<case>, <constant> or <system>; environment variables, $FOAMFMI_DIR of the
tutorials' shared dictionaries, expanded); '$name;' in a dictionary (the entries of
the dictionary `name`, looked up in the enclosing dictionaries, merged in);
'$name' in a value (its tokens spliced in); 'a.b' in a name reaches into a
sub-dictionary, '$:a.b' starts at the file's top. Other directives
(#calc, #codeStream, #includeEtc, ...) and their argument are skipped.

    d = expanded(case, "constant/dynamicMeshDict")

reads a case's dictionary as OpenFOAM does instead (foamDictionary -expand:
every directive, #eval and #calc included, done by OpenFOAM itself), then
parses what it prints.
"""

import copy
import os
import re
import shutil
import subprocess
import tempfile

from foamfmi.dictionary import DictionaryError, strip_comments

_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[{}()\[\];]|[^\s{}()\[\];"]+')
_OPEN, _CLOSE = "{([", "})]"


class _Scope(dict):
    """A dictionary that knows the one it stands in ($name lookups)."""

    def __init__(self, parent=None):
        super().__init__()
        self.parent = parent


def expanded(case, name, precision=None):
    """The dictionary file case/name as OpenFOAM reads it (foamDictionary
    -expand), parsed; DictionaryError when OpenFOAM cannot read it (its
    message) or foamDictionary is not found. precision: the digits of the
    numbers it prints (default OpenFOAM's, 6; 17 gives every double as
    read)."""
    if shutil.which("foamDictionary") is None:
        raise DictionaryError("%s: foamDictionary not found: source OpenFOAM's environment "
                              "(. etc/bashrc in the project)" % name)
    case = os.path.abspath(case)
    # In the case's folder, with PWD saying so (else OpenFOAM warns on
    # standard output, before the dictionary)
    digits = [] if precision is None else ["-precision", str(precision)]
    done = subprocess.run(["foamDictionary", "-case", case, "-expand", name] + digits, cwd=case,
                          env={**os.environ, "PWD": case}, capture_output=True, text=True)
    if done.returncode != 0:
        message = (done.stderr + done.stdout).strip()
        message = re.sub(r"\n\s*\n(\s*\n)+", "\n\n", message)
        start = message.find("FOAM FATAL")
        raise DictionaryError("%s: OpenFOAM cannot read it (foamDictionary -expand):\n%s"
                              % (name, message[start:] if start >= 0 else message))
    # The dictionary starts at OpenFOAM's banner; a warning may come before it
    start = done.stdout.find("/*---")
    with tempfile.NamedTemporaryFile("w", suffix=".expanded") as f:
        f.write(done.stdout[max(start, 0):])
        f.flush()
        return parse(f.name, case)


def parse(path, case=None):
    """The dictionary file at path; case: the folder of <case>,
    <constant>, <system> (default: the file's folder's parent)."""
    if case is None:
        case = os.path.dirname(os.path.dirname(os.path.abspath(path)))
    top = _Scope()
    _parse_file(path, top, case)
    return top


def vector(tokens):
    """The numbers of a value '(x y z ...)' as floats."""
    words = [t for t in tokens if t not in "()"]
    try:
        return [float(w) for w in words]
    except ValueError:
        raise DictionaryError("not a list of numbers: %s" % " ".join(tokens)) from None


def word(tokens):
    """A one-word value, its quotes removed."""
    if len(tokens) != 1:
        raise DictionaryError("not a single word: %s" % " ".join(tokens))
    return tokens[0].strip('"')


def _parse_file(path, scope, case):
    try:
        with open(path) as f:
            text = strip_comments(f.read())
    except OSError as error:
        raise DictionaryError("cannot read %s: %s" % (path, error)) from None
    tokens = _TOKEN.findall(text)
    position = _parse_entries(tokens, 0, scope, os.path.dirname(path), case)
    if position != len(tokens):
        raise DictionaryError("%s: unbalanced '}'" % path)
    scope.pop("FoamFile", None)


def _parse_entries(tokens, i, scope, folder, case):
    """Entries into scope from tokens[i] up to the closing '}' (its index)."""
    while i < len(tokens) and tokens[i] != "}":
        key = tokens[i]
        i += 1
        if key == ";":
            continue
        if key.startswith("#"):
            argument = tokens[i] if i < len(tokens) else ""
            i += 1
            if key in ("#include", "#includeIfPresent", "#sinclude"):
                name = _include_path(argument.strip('"'), folder, case)
                if os.path.isfile(name) or key == "#include":
                    _parse_file(name, scope, case)
            continue
        if key.startswith("$") and i < len(tokens) and tokens[i] == ";":
            found = _lookup(scope, key[1:])
            if not isinstance(found, dict):
                raise DictionaryError("%s: not a dictionary" % key)
            for name, value in found.items():
                scope[name] = _copy(value, scope)
            i += 1
            continue
        if i < len(tokens) and tokens[i] == "{":
            if not isinstance(scope.get(key), dict):
                scope[key] = _Scope(scope)
            i = _parse_entries(tokens, i + 1, scope[key], folder, case) + 1
            continue
        value, i = _value(tokens, i, scope)
        scope[key] = value
    return i


def _value(tokens, i, scope):
    """The tokens of a value up to its ';' at depth 0, $names spliced."""
    value, depth = [], 0
    while i < len(tokens):
        t = tokens[i]
        i += 1
        if t == ";" and depth == 0:
            break
        if t in _OPEN:
            depth += 1
        elif t in _CLOSE:
            depth -= 1
        if t.startswith("$") and len(t) > 1:
            found = _lookup(scope, t[1:])
            if isinstance(found, dict):
                return _copy(found, scope), _skip_to_semicolon(tokens, i)
            value += found
        else:
            value.append(t)
    return value, i


def _skip_to_semicolon(tokens, i):
    while i < len(tokens) and tokens[i] != ";":
        i += 1
    return i + 1


def _lookup(scope, name):
    """$name: the entry in scope or the nearest enclosing one; 'a.b'
    reaches into a; ':a' starts at the top."""
    name = name.strip("{}")
    if name.startswith(":"):
        while scope.parent is not None:
            scope = scope.parent
        name = name[1:]
    first, *rest = name.split(".")
    # A keyword that itself contains dots (A.p) wins over a path
    while scope is not None and first not in scope and name not in scope:
        scope = scope.parent
    if scope is None:
        raise DictionaryError("$%s: no such entry" % name)
    if name in scope:
        return scope[name]
    found = scope[first]
    for part in rest:
        if not isinstance(found, dict) or part not in found:
            raise DictionaryError("$%s: no such entry" % name)
        found = found[part]
    return found


def _copy(value, parent):
    if isinstance(value, dict):
        out = _Scope(parent)
        for name, item in value.items():
            out[name] = _copy(item, out)
        return out
    return copy.copy(value)


_ENVIRONMENT = re.compile(r"\$\{(\w+)\}|\$(\w+)")


def _include_path(name, folder, case):
    for tag, base in (("<case>", case), ("<constant>", os.path.join(case, "constant")),
                      ("<system>", os.path.join(case, "system")),
                      ("$FOAM_CASE", case)):
        if name.startswith(tag):
            return os.path.join(base, name[len(tag):].lstrip("/"))

    def variable(match):
        key = match.group(1) or match.group(2)
        if key not in os.environ:
            raise DictionaryError("#include \"%s\": the environment variable %s is not set"
                                  % (name, key))
        return os.environ[key]

    name = _ENVIRONMENT.sub(variable, name)
    return name if os.path.isabs(name) else os.path.join(folder, name)

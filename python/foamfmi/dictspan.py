"""Where a dictionary entry stands in an OpenFOAM dictionary file's text, so
that it can be replaced in place, the rest of the file (comments,
#include, #eval, #codeStream, $macros) kept as written.

    spans = dictionary_spans(text)
    start, end = spans[("rigidBodyMotionCoeffs", "restraints", "spring")]
    text = text[:start] + replacement + text[end:]

A span runs from the first character of the entry's keyword to the end of
its closing '}' (a dictionary entry) or its ';' (any other entry). Only
entries written in the text are found: one that an #include or a $macro
brings in has no span. Comments, strings and #{ ... #} verbatim blocks are
skipped when the braces are counted.
"""

import re

from foamfmi.dictionary import DictionaryError

_TOKEN = re.compile(r'//[^\n]*|/\*.*?\*/|#\{.*?#\}|"(?:[^"\\]|\\.)*"'
                    r'|[{}()\[\];]|[^\s{}()\[\];"/]+|/', re.S)
_OPEN, _CLOSE = "{([", "})]"


def _tokens(text):
    """(token, start, end) of text, without comments."""
    for match in _TOKEN.finditer(text):
        token = match.group(0)
        if token.startswith("//") or token.startswith("/*"):
            continue
        yield token, match.start(), match.end()


def dictionary_spans(text, path=""):
    """{(keyword, ...): (start, end)} of every entry of text, by its path
    of keywords from the top (path: the file's name, for errors)."""
    spans = {}
    tokens = list(_tokens(text))
    i = _entries(tokens, 0, (), spans, path)
    if i != len(tokens):
        raise DictionaryError("%s: unbalanced '}' at character %d" % (path, tokens[i][1]))
    return spans


def _entries(tokens, i, scope, spans, path):
    """Entries from tokens[i] to the '}' that closes scope (its index)."""
    while i < len(tokens) and tokens[i][0] != "}":
        key, start, _ = tokens[i]
        i += 1
        if key == ";":
            continue
        if key.startswith("#") and key not in ("#eval", "#calc", "#codeStream"):
            i += 1  # a directive and its argument: #include "file", #inputMode merge
            continue
        if i < len(tokens) and tokens[i][0] == "{":
            i = _entries(tokens, i + 1, scope + (key,), spans, path)
            if i >= len(tokens):
                raise DictionaryError("%s: entry %s: no closing '}'"
                                      % (path, ".".join(scope + (key,))))
            spans[scope + (key,)] = (start, tokens[i][2])
            i += 1
            continue
        depth = 0
        while i < len(tokens) and not (tokens[i][0] == ";" and depth == 0):
            depth += (tokens[i][0] in _OPEN) - (tokens[i][0] in _CLOSE)
            i += 1
        if i >= len(tokens):
            raise DictionaryError("%s: entry %s: no ';' at its end"
                                  % (path, ".".join(scope + (key,))))
        spans[scope + (key,)] = (start, tokens[i][2])
        i += 1
    return i


def indentation(text, start):
    """The white space before position start on its line."""
    line_start = text.rfind("\n", 0, start) + 1
    prefix = text[line_start:start]
    return prefix if not prefix.strip() else ""

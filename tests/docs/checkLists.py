#!/usr/bin/env python3
"""The lists in the documentation that name the tree's parts are checked
against the tree, so that they cannot go stale:

- every folder named in the first column of docs/layout.md's layout table
  exists;
- every connector (a folder of connectors/ but common/) is named in
  docs/layout.md's fmu/ row and in connectors/README.md;
- every library and application that foam-fmi-bridge/ builds (the LIB and
  EXE of each Make/files) is named in docs/layout.md's foam-fmi-bridge/ row;
- every tutorial (a folder of tutorials/ with an Allrun) is named in
  tutorials/README.md;
- every relative link of every Markdown file in git leads to a file or
  folder that exists and, for a heading anchor in a Markdown file (#name),
  to one of its headings (GitHub's names: lower case, punctuation dropped,
  spaces as hyphens); files copied unchanged from a data set
  (experiment/data/) link into its own repository and are left out.

Usage: checkLists.py [REPOSITORY]
"""
import os
import re
import subprocess
import sys


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def layout_rows(readme):
    """{first-column text: row} of docs/layout.md's table under ## Layout."""
    section = readme.split("\n## Layout\n", 1)[1].split("\n## ", 1)[0]
    rows = {}
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 2 and cells[0] not in ("folder", "---"):
            rows[cells[0]] = line
    return rows


def heading_anchors(text):
    """GitHub's anchors of a Markdown file's headings."""
    anchors = set()
    in_code = False
    for line in text.splitlines():
        if line.startswith("```"):
            in_code = not in_code
        match = re.match(r"#{1,6} +(.*?) *#* *$", line)
        if match and not in_code:
            name = re.sub(r"[^\w\- ]", "", match.group(1).lower()).replace(" ", "-")
            anchors.add(name)
    return anchors


def link_problems(top):
    """Relative links of the Markdown files in git that lead nowhere."""
    files = subprocess.run(["git", "-C", top, "ls-files", "*.md"], check=True,
                           capture_output=True, text=True).stdout.split()
    problems = []
    for name in files:
        if "/experiment/data/" in name:
            continue  # copied unchanged from a data set: links into its repository
        text = read(os.path.join(top, name))
        prose = re.sub(r"```.*?```", "", text, flags=re.S)
        for target in re.findall(r"\]\(([^)\s]+)\)", prose):
            if re.match(r"[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            full = os.path.normpath(os.path.join(top, os.path.dirname(name), path)) if path \
                else os.path.join(top, name)
            if not os.path.exists(full):
                problems.append(f"{name}: link {target}: {path} does not exist")
            elif anchor and full.endswith(".md") and anchor not in heading_anchors(read(full)):
                problems.append(f"{name}: link {target}: no heading #{anchor} in "
                                f"{os.path.relpath(full, top)}")
    return problems, len(files)


def main():
    top = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                          os.path.join(os.path.dirname(__file__), "..", ".."))
    rows = layout_rows(read(os.path.join(top, "docs", "layout.md")))
    problems, nMarkdown = link_problems(top)

    for first in rows:
        for path in re.findall(r"`([^`]+)`", first):
            if not os.path.exists(os.path.join(top, path)):
                problems.append(f"docs/layout.md layout table: {path} does not exist")

    def row(folder):
        found = [r for first, r in rows.items() if f"`{folder}`" in first]
        if not found:
            problems.append(f"docs/layout.md layout table: no row for {folder}")
            return ""
        return found[0]

    connectors = sorted(d for d in os.listdir(os.path.join(top, "connectors"))
                        if os.path.isdir(os.path.join(top, "connectors", d)) and d != "common")
    fmu_row = row("fmu/")
    connectors_readme = read(os.path.join(top, "connectors", "README.md"))
    for name in connectors:
        if f"`{name}`" not in fmu_row:
            problems.append(f"docs/layout.md layout table, fmu/: connector {name} not named")
        if f"`{name}/`" not in connectors_readme:
            problems.append(f"connectors/README.md: connector {name}/ not named")

    bridge_row = row("foam-fmi-bridge/")
    bridge = os.path.join(top, "foam-fmi-bridge")
    for folder, _, files in os.walk(bridge):
        if os.path.basename(folder) == "Make" and "files" in files:
            text = read(os.path.join(folder, "files"))
            for kind, name in re.findall(r"^(LIB|EXE)\s*=\s*\S*/(\w+)\s*$", text, re.M):
                shown = f"{name}.so" if kind == "LIB" else name
                if f"`{shown}`" not in bridge_row:
                    problems.append(f"docs/layout.md layout table, foam-fmi-bridge/: "
                                    f"{shown} ({os.path.relpath(folder, top)}) not named")

    tutorials_readme = read(os.path.join(top, "tutorials", "README.md"))
    tutorials = sorted(d for d in os.listdir(os.path.join(top, "tutorials"))
                       if os.path.isfile(os.path.join(top, "tutorials", d, "Allrun")))
    for name in tutorials:
        if not re.search(rf"\b{name}\b", tutorials_readme):
            problems.append(f"tutorials/README.md: tutorial {name} not named")

    for problem in problems:
        print("FAIL [docs.lists]:", problem, file=sys.stderr)
    if problems:
        sys.exit(1)
    print(f"ok   [docs.lists]: {len(rows)} layout rows, {len(connectors)} connectors, "
          f"{len(tutorials)} tutorials named where they are listed; the relative links "
          f"of {nMarkdown} Markdown files lead where they say")


if __name__ == "__main__":
    main()

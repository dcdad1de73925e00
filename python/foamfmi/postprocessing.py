"""What the runs write, read as the analyses need it: whitespace tables
(postProcessing/rigidBodyMotion/<body>.dat of rigidBodyMotionFromLog, the
connectors' postProcessing/fmuConnectors/<time>/<name>.dat with their
'# Time ...' header), the probes of a function object
(postProcessing/<name>/<time>/<field>), the free-surface elevation at a
vertical line of probes of alpha.water (a wave gauge), and the counts of a
solver log.
"""

import os
import re
import subprocess


class PostProcessingError(ValueError):
    """A file without the rows or columns asked for."""


def read_table(path):
    """Rows of numbers of a whitespace table, '#' lines skipped, rows of
    another length than the first (a line cut by a stopped run) left out.
    A last line without its newline is read (digitised curves often end
    so); read_named_table, for the tables runs write, leaves it out."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            values = line.split()
            if rows and len(values) != len(rows[0]):
                continue
            rows.append([float(v) for v in values])
    if not rows:
        raise PostProcessingError("no rows in " + path)
    return rows


def whole_rows(path, cut_end=False):
    """(rows, longest row in bytes) of a table written in whole rows (a
    connector's, bodies.dat, fmuConnectorFlow's samples); PostProcessingError
    when it ends in a cut row or a row has another number of columns than
    its last '#' header line names. cut_end: a cut last row (one without
    its newline, as a kill -9 inside a write leaves) is left out instead."""
    with open(path, "rb") as f:
        data = f.read()
    if data and not data.endswith(b"\n"):
        if not cut_end:
            raise PostProcessingError(f"{path}: ends in a cut row: {data[-80:]!r}")
        data = data[:data.rfind(b"\n") + 1]
    columns, rows, longest = None, 0, 0
    for line in data.decode().splitlines():
        if line.startswith("#"):
            columns = len(line[1:].split())
            continue
        if len(line.split()) != columns:
            raise PostProcessingError(f"{path}: row {rows + 1} has {len(line.split())} "
                                      f"columns, the header {columns}")
        rows += 1
        longest = max(longest, len(line) + 1)
    return rows, longest


def read_header(path):
    """The column names of the '# Time ...' header line of a table (a
    connector's output), Time first; PostProcessingError without one."""
    with open(path) as f:
        for line in f:
            if re.match(r"#\s*Time\s", line):
                return line[1:].split()
    raise PostProcessingError(path + ": no '# Time ...' header line")


def header_column(path, name):
    """Index (0-based, time = 0) of NAME in the '# Time ...' header."""
    try:
        names = read_header(path)
    except PostProcessingError:
        names = []
    if name not in names:
        raise PostProcessingError("no column %s in %s" % (name, path))
    return names.index(name)


def read_named_table(path):
    """(names, rows) of a table with a '# Time ...' header: the whole rows
    with as many numbers as the header has names (a line cut by a stopped
    run, which may lack numbers or its newline, is left out)."""
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if not line.endswith("\n"):
                break
            if line.startswith("#"):
                if re.match(r"#\s*Time\s", line):
                    names = line[1:].split()
                continue
            values = line.split()
            if not values:
                continue
            if names is None:
                raise PostProcessingError(path + ": no '# Time ...' header before the rows")
            if len(values) == len(names):
                rows.append([float(v) for v in values])
    if names is None:
        raise PostProcessingError(path + ": no '# Time ...' header line")
    return names, rows


def read_columns(path, names):
    """Rows [time, the named columns...] of a table with a '# Time ...'
    header (a connector's output)."""
    header, rows = read_named_table(path)
    missing = [n for n in names if n not in header]
    if missing:
        raise PostProcessingError("%s: no column %s in the header" % (path, ", ".join(missing)))
    if not rows:
        raise PostProcessingError("no rows in " + path)
    index = [0] + [header.index(n) for n in names]
    return [[r[i] for i in index] for r in rows]


def read_probes(base, field):
    """The probes of a function object: base is postProcessing/<name>, with
    a folder per start time holding the file field. Returns the probe
    points [(x, y, z)], the times and the rows of values (one per probe),
    the time folders read in order; a time written again after a restart
    is taken from the first folder that has it. The points must be the
    same in every folder."""
    if not os.path.isdir(base):
        raise PostProcessingError("no " + base)
    points, times, rows = None, [], []
    for start in sorted(os.listdir(base), key=float):
        path = os.path.join(base, start, field)
        probe_points = []
        with open(path) as f:
            for line in f:
                if line.startswith("# Probe") and "(" in line:
                    xyz = line[line.index("(") + 1:line.index(")")].split()
                    probe_points.append(tuple(float(v) for v in xyz))
                elif line.startswith("#") or not line.strip():
                    continue
                else:
                    values = line.split()
                    if len(values) != len(probe_points) + 1:
                        continue  # a line cut by a stopped run
                    t = float(values[0])
                    if times and t <= times[-1]:
                        continue  # a restart repeats times
                    times.append(t)
                    rows.append([float(v) for v in values[1:]])
        if points is None:
            points = probe_points
        elif probe_points != points:
            raise PostProcessingError("the probes differ between the time folders of " + base)
    if not times:
        raise PostProcessingError("no samples in " + base)
    return points, times, rows


def gauge_lines(points):
    """The probes grouped into vertical lines: [(x, [(z, index)...])],
    sorted by x and, in each line, by z."""
    lines = {}
    for i, (x, _, z) in enumerate(points):
        lines.setdefault(x, []).append((z, i))
    return [(x, sorted(line)) for x, line in sorted(lines.items())]


def elevation(rows, line, depth, bottom=None):
    """Free-surface elevation above the still water (depth) at a gauge: a
    vertical line [(z, index)...] (sorted by z) of alpha.water probes at
    the centres of a column of cells, the water below the column full, the
    air above it empty: eta = z_bottom + sum(dz_i alpha_i) - depth.

    bottom None: equal cells, dz = the points' spacing, z_bottom = z_1 -
    dz/2. bottom given: graded cells whose lowest face is at bottom, the
    faces following from the centres (f_i+1 = 2 z_i - f_i).

    Returns eta for every row and the number of rows whose lowest probe is
    not water (alpha < 0.99) or highest not air (alpha > 0.01)."""
    columns = [i for _, i in line]
    outside = sum(1 for row in rows if row[columns[0]] < 0.99 or row[columns[-1]] > 0.01)
    if bottom is None:
        dz = (line[-1][0] - line[0][0]) / (len(line) - 1)
        z_bottom = line[0][0] - 0.5 * dz
        eta = [z_bottom + dz * sum(row[i] for i in columns) - depth for row in rows]
        return eta, outside
    heights, face = [], bottom
    for z, _ in line:
        top = 2 * z - face
        if top <= face:
            raise PostProcessingError("the probes at z = %s are not the centres of cells "
                                      "from z = %g" % (" ".join("%g" % p for p, _ in line),
                                                       bottom))
        heights.append(top - face)
        face = top
    eta = [bottom + sum(dz * row[i] for dz, i in zip(heights, columns)) - depth
           for row in rows]
    return eta, outside


def read_gauges(case, depth, bottom=None, name="waveGauges"):
    """Times and {x: eta(t)} of the wave gauges of a case: the lines of
    alpha.water probes of CASE/postProcessing/<name> (elevation())."""
    base = os.path.join(case, "postProcessing", name)
    if not os.path.isdir(base):
        raise PostProcessingError("no %s (did the solver run with system/%s?)" % (base, name))
    points, times, rows = read_probes(base, "alpha.water")
    return times, {x: elevation(rows, line, depth, bottom)[0] for x, line in gauge_lines(points)}


def case_solver(case):
    """The solver a tutorial case runs here (tutorialFunctions' caseSolver:
    its controlDict's application, or on your own OpenFOAM without the
    rebuilt solvers the solver they are built from); its log is
    log.<solver>."""
    top = os.environ.get("FOAMFMI_DIR") or os.path.dirname(
        os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    functions = os.path.join(top, "tutorials", "bin", "tutorialFunctions")
    return subprocess.run(["sh", "-c", '. "$0" && caseSolver', functions], cwd=case,
                          check=True, stdout=subprocess.PIPE, text=True).stdout.strip()


def solver_log(path):
    """Counts of a solver log: time steps ('Time = ' lines), the last
    ExecutionTime (s, None if none) and implicitNewmark's summary line
    (solves, Newton iterations, evaluations; None if none)."""
    steps, execution, newmark = 0, None, None
    with open(path) as f:
        for line in f:
            if line.startswith("Time = "):
                steps += 1
            elif line.startswith("ExecutionTime = "):
                execution = float(line.split()[2])
            m = re.match(r"Rigid-body solver implicitNewmark: (\d+) solves, (\d+) Newton"
                         r" iterations, (\d+) evaluations", line)
            if m:
                newmark = tuple(int(g) for g in m.groups())
    return {"timeSteps": steps, "executionTime": execution, "implicitNewmark": newmark}


def run_settings(case):
    """The settings an Allrun wrote to CASE/log.runSettings ("meshFactor
    0.5; endTime 12; ..."): {'meshFactor': '0.5', ...}."""
    path = os.path.join(case, "log.runSettings")
    if not os.path.isfile(path):
        raise PostProcessingError("no %s (written by Allrun)" % path)
    settings = {}
    with open(path) as f:
        for item in f.read().split(";"):
            words = item.split()
            if len(words) == 2:
                settings[words[0]] = words[1]
    return settings


def mesh_cells(path):
    """The cell count of a checkMesh log (None without one)."""
    if os.path.isfile(path):
        with open(path) as f:
            for line in f:
                if line.strip().startswith("cells:"):
                    return int(line.split()[1])
    return None


def project_commit():
    """The project's commit: FOAMFMI_COMMIT, else git describe of
    FOAMFMI_DIR, else 'unknown'."""
    if os.environ.get("FOAMFMI_COMMIT"):
        return os.environ["FOAMFMI_COMMIT"]
    top = os.environ.get("FOAMFMI_DIR", ".")
    try:
        out = subprocess.run(["git", "-C", top, "describe", "--always", "--dirty"],
                             capture_output=True, text=True, check=True)
        return out.stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def read_key_values(path):
    """The "key value" lines of a file ('#' lines skipped): {key: value},
    the value a float where it reads as one, else the text."""
    values = {}
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            key, value = line.split(None, 1)
            value = value.strip()
            try:
                values[key] = float(value)
            except ValueError:
                values[key] = value
    return values


def write_kept_run(folder, run, series, columns, run_title, series_title):
    """What a case's analysis keeps of a run: folder/run.dat, one "key
    value" a line under '# run_title' (floats with 9 digits), and
    folder/series.dat, the series' columns (7 digits) under
    '# series_title' and '# <columns>'."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "run.dat"), "w") as f:
        f.write("# %s\n" % run_title)
        for key in sorted(run):
            value = run[key]
            f.write("%s %s\n" % (key, "%.9g" % value if isinstance(value, float) else value))
    with open(os.path.join(folder, "series.dat"), "w") as f:
        f.write("# %s\n" % series_title)
        f.write("# " + " ".join(columns) + "\n")
        for j in range(len(series[columns[0]])):
            f.write(" ".join("%.7g" % series[c][j] for c in columns) + "\n")


def read_kept_run(folder, columns, keys):
    """(run, series) of a folder written by write_kept_run: run the
    {key: value} of run.dat, which must have every one of keys, series
    {column: array} of series.dat, which must have every one of columns."""
    import numpy as np  # only here: the rest of the module reads tables without it

    path = os.path.join(folder, "run.dat")
    run = read_key_values(path)
    missing = [k for k in keys if k not in run]
    if missing:
        raise PostProcessingError("%s: no %s" % (path, ", ".join(missing)))
    names, rows = read_named_table(os.path.join(folder, "series.dat"))
    missing = [c for c in columns if c not in names]
    if missing:
        raise PostProcessingError("%s/series.dat: no column %s" % (folder, ", ".join(missing)))
    table = np.array(rows)
    return run, {c: table[:, names.index(c)] for c in columns}

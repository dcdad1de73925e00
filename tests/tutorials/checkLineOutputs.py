"""Checks of the line outputs of a tutorial run with mooring lines.

Usage: checkLineOutputs.py CASE LINE... [--flow NAME --solver APP]

For each LINE (an fmuConnector restraint whose FMU reports a shape):
  - VTK/fmuConnectors/LINE.vtk.series lists one file per write time of the
    case, in order, and each file exists;
  - each VTK file holds the row of that time of the connector's output
    file postProcessing/fmuConnectors/0/LINE.dat: its points are
    shape.x/y/z[k] and its point data `tension` is shape.tension[k]. The
    two files are written from the same double values, the VTK file with
    the case's writePrecision (12 significant digits): tolerance 1e-10 of
    the largest coordinate (or tension), and nothing less.

With --flow NAME (the fmuConnectorFlow function object of the case):
  - postProcessing/NAME/0/LINE.dat has one row per time step of the
    connector file, at the same times;
  - at the last write time, its row is OpenFOAM's own probe of U
    (`APP -postProcess`, the `probes` function object with the cellPoint
    interpolation) at the points of that time's VTK file: the sampled
    velocity is U interpolated at the line's points of the end of the
    step. Tolerance 1e-8 of the largest speed plus 1e-12 m/s: the probe
    reads U back from the 12-digit time directory and interpolates in the
    mesh the time directory holds, which has its points to 12 digits too;
    A point the probe does not find in the mesh (OpenFOAM reports -1e300)
    lies on the mesh's boundary: the grounded part of a line, pressed a
    few um into the tank floor by the seabed penalty, or a fairlead on the
    body's surface, where the cell a point on a face falls in is a matter
    of round-off; those points are not compared;
  - the water around the line moves at that time (largest sampled speed
    above 1e-6 m/s, at least three points in the mesh): a sampling that
    gave zero velocity would fail.
Prints what it found; exits non-zero at the first failure.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys

from foamfmi import cli, postprocessing


def fail(msg):
    sys.exit(f"checkLineOutputs: {msg}")


def read_table(path):
    """Header names (of the '# Time ...' line) and rows."""
    try:
        names, rows = postprocessing.read_named_table(path)
    except postprocessing.PostProcessingError:
        names, rows = None, []
    if names is None or not rows:
        fail(f"{path}: no header or no rows")
    return names, rows


def read_vtk(path):
    """Points and point data 'tension' (None if absent) of a legacy VTK
    polyline written by the bridge."""
    with open(path) as f:
        tokens = f.read().split("\n")
    points, tension = [], None
    i = 0
    while i < len(tokens):
        words = tokens[i].split()
        if words[:1] == ["POINTS"]:
            n = int(words[1])
            points = [[float(v) for v in tokens[i + 1 + k].split()] for k in range(n)]
            i += n
        elif words[:2] == ["SCALARS", "tension"]:
            n = len(points)
            tension = [float(tokens[i + 2 + k]) for k in range(n)]
            i += n + 1
        elif words[:1] == ["LINES"]:
            ids = [int(v) for v in tokens[i + 1].split()]
            if ids != [len(points)] + list(range(len(points))):
                fail(f"{path}: LINES {ids}: expected one polyline through every point")
        i += 1
    if len(points) < 2:
        fail(f"{path}: fewer than two points")
    return points, tension


def write_times(case):
    times = []
    for entry in os.listdir(case):
        if re.fullmatch(r"[0-9.eE+-]+", entry) and os.path.isdir(os.path.join(case, entry)):
            t = float(entry)
            if t > 0:
                times.append((t, entry))
    return sorted(times)


def check_vtk(case, line, times):
    series_path = os.path.join(case, "VTK", "fmuConnectors", line + ".vtk.series")
    if not os.path.isfile(series_path):
        fail(f"{series_path} missing")
    with open(series_path) as f:
        series = json.load(f)["files"]
    listed = [e["time"] for e in series]
    expected = [t for t, _ in times]
    if len(listed) != len(expected) or any(
        abs(a - b) > 1e-9 * max(1.0, abs(b)) for a, b in zip(listed, expected)
    ):
        fail(f"{series_path}: times {listed}, the case's write times {expected}")

    names, rows = read_table(
        os.path.join(case, "postProcessing", "fmuConnectors", "0", line + ".dat")
    )
    col = {n: i for i, n in enumerate(names)}
    n = sum(1 for name in names if name.startswith("shape.x["))
    worst_p = worst_t = 0.0
    last = None
    for entry in series:
        t = entry["time"]
        row = min(rows, key=lambda r: abs(r[0] - t))
        if abs(row[0] - t) > 1e-9 * max(1.0, t):
            fail(f"{line}.dat: no row at the write time {t}")
        points, tension = read_vtk(os.path.join(os.path.dirname(series_path), entry["name"]))
        if len(points) != n:
            fail(f"{entry['name']}: {len(points)} points, {n} shape points in {line}.dat")
        scale = max(abs(row[col[f"shape.{a}[{k}]"]]) for k in range(1, n + 1) for a in "xyz")
        for k, p in enumerate(points, start=1):
            for a, v in zip("xyz", p):
                e = abs(v - row[col[f"shape.{a}[{k}]"]])
                worst_p = max(worst_p, e)
                # 12 significant digits in the VTK file (see the docstring)
                if e > 1e-10 * scale:
                    fail(f"{entry['name']}: point {k} {a} = {v}, {line}.dat has "
                         f"{row[col[f'shape.{a}[{k}]']]} at t = {t}")
        if f"shape.tension[1]" in col:
            if tension is None:
                fail(f"{entry['name']}: no point data tension, {line}.dat has shape.tension")
            tscale = max(abs(row[col[f"shape.tension[{k}]"]]) for k in range(1, n + 1))
            for k, v in enumerate(tension, start=1):
                e = abs(v - row[col[f"shape.tension[{k}]"]])
                worst_t = max(worst_t, e)
                if e > 1e-10 * tscale:
                    fail(f"{entry['name']}: tension {k} = {v}, {line}.dat has "
                         f"{row[col[f'shape.tension[{k}]']]} at t = {t}")
        last = points
    print(f"{line}: VTK at the {len(series)} write times = the shape rows of "
          f"{line}.dat (points within {worst_p:.2g} m, tension within {worst_t:.2g} N)")
    return rows, last


def probe(case, solver, time_name, points):
    """U at the points by OpenFOAM's probes (cellPoint) at a written time."""
    locations = "\n".join(f"        ({p[0]!r} {p[1]!r} {p[2]!r})" for p in points)
    with open(os.path.join(case, "system", "probeLine"), "w") as f:
        f.write(f"""FoamFile {{ version 2.0; format ascii; class dictionary; object probeLine; }}
functions
{{
    probeLine
    {{
        type                probes;
        libs                ("libsampling.so");
        fields              (U);
        interpolationScheme cellPoint;
        probeLocations
        (
{locations}
        );
    }}
}}
""")
    base = os.path.join(case, "postProcessing", "probeLine")
    shutil.rmtree(base, ignore_errors=True)
    out = subprocess.run(
        [solver, "-postProcess", "-dict", "system/probeLine", "-time", time_name],
        cwd=case, capture_output=True, text=True,
    )
    if out.returncode != 0:
        fail(f"{solver} -postProcess (probes) failed:\n{out.stdout[-2000:]}{out.stderr[-2000:]}")
    # v1912 writes the probes under the time probed, v2312 under the
    # controlDict's start time: the one folder there is
    folders = os.listdir(base) if os.path.isdir(base) else []
    if len(folders) != 1:
        fail(f"{base}: {len(folders)} folders after probing one time, expected one")
    path = os.path.join(base, folders[0], "U")
    values = None
    with open(path) as f:
        for line in f:
            if not line.startswith("#") and line.strip():
                values = [float(v) for v in re.findall(r"[-+0-9.eE]+", line)]
    if not values:
        fail(f"{path}: no probe values")
    u = values[1:]
    return [u[3 * k:3 * k + 3] for k in range(len(points))]


def check_flow(case, line, name, solver, line_rows, points, time_name):
    names, rows = read_table(os.path.join(case, "postProcessing", name, "0", line + ".dat"))
    if len(rows) != len(line_rows) or any(
        abs(a[0] - b[0]) > 1e-9 * max(1.0, b[0]) for a, b in zip(rows, line_rows)
    ):
        fail(f"postProcessing/{name}/0/{line}.dat: {len(rows)} rows, the connector "
             f"file {len(line_rows)}, or different times")
    t = float(time_name)
    row = min(rows, key=lambda r: abs(r[0] - t))
    sampled = [row[1 + 3 * k:4 + 3 * k] for k in range(len(points))]
    probed = probe(case, solver, time_name, points)
    outside = [k for k, u in enumerate(probed) if max(abs(c) for c in u) > 1e299]
    for k in outside:
        probed[k] = sampled[k]
    if len(points) - len(outside) < 3:
        fail(f"{line} at t = {time_name}: only {len(points) - len(outside)} points in the mesh")
    speed = max(math.sqrt(sum(c * c for c in u))
                for k, u in enumerate(probed) if k not in outside)
    worst = 0.0
    for k, (s, p) in enumerate(zip(sampled, probed), start=1):
        e = max(abs(a - b) for a, b in zip(s, p))
        worst = max(worst, e)
        # U read back from 12 digits, mesh points too (see the docstring)
        if e > 1e-8 * speed + 1e-12:
            fail(f"{line} at t = {time_name}, point {k}: sampled U {s}, probes {p}")
    if speed < 1e-6:
        fail(f"{line} at t = {time_name}: the water at the line is still "
             f"(largest speed {speed:.3g} m/s): nothing to check the sampling with")
    print(f"{line}: water velocity at t = {time_name} = OpenFOAM's probes of U at the "
          f"line's points within {worst:.2g} m/s (largest speed {speed:.3g} m/s; "
          f"{len(outside)} points on the boundary, not compared); one row per step")


def main(argv):
    p = cli.parser("checkLineOutputs.py", __doc__)
    p.add_argument("case", metavar="CASE")
    p.add_argument("lines", nargs="+", metavar="LINE")
    p.add_argument("--flow", metavar="NAME", help="the fmuConnectorFlow function object")
    p.add_argument("--solver", metavar="APP", help="the solver, with --flow")
    args = p.parse_args(argv)
    if args.flow and not args.solver:
        fail("usage: checkLineOutputs.py CASE LINE... [--flow NAME --solver APP]")
    case, lines, flow, solver = args.case, args.lines, args.flow, args.solver
    times = write_times(case)
    if not times:
        fail(f"{case}: no written time")
    for line in lines:
        rows, last_points = check_vtk(case, line, times)
        if flow:
            check_flow(case, line, flow, solver, rows, last_points, times[-1][1])


if __name__ == "__main__":
    main(sys.argv[1:])

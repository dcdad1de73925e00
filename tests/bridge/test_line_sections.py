"""The VTK polylines of lines of sections: each point's section.

A body on a prismatic x joint is moored to a seabed anchor 40 m below its
fairlead by three lines: a catenary.fmu line of two sections (a 70 m chain
from the anchor, then a 50 m rope), the same line as mooringLine.fmu, and a
uniform catenary.fmu line. After a few steps the bridge writes each as a
legacy VTK polyline of the FMU's 11 shape points (VTK/fmuConnectors/).

The lines of sections carry the point data `section`: the 0-based index,
from the anchor, of the section each point lies in. The shape points lie at
equal steps of unstretched arc from the fairlead (point 1) to the anchor
(point 11), 12 m apart here, so points 1 to 5 (arcs 120 to 72 m from the
anchor) lie in the rope (index 1) and points 6 to 11 (arcs 60 to 0 m) in
the chain (index 0); computed here from the lengths, not from the FMU.
The uniform line's file has no `section` field (its VTK is what it was
before sections), and every file keeps its `tension` point data.

mooringLine.fmu reports its joint as outputs (joint.x/y/z[1],
section.lowerTension[2]): its file has the joint as a 12th point, a vertex,
where the row of the connector's .dat at the written time has it (the same
doubles), with the rope's lower-end tension and the rope's index (1).
catenary.fmu's joints are local variables, which the bridge does not read:
its file has the 11 shape points only.
"""
import math
import os
import sys

from foamfmi.bridgecase import Case, check, fmu_path, rigid_body, summary, vec

CHAIN, ROPE, EA, DEPTH, X0 = 70.0, 50.0, 5e7, 40.0, 100.0
W_CHAIN, W_ROPE = 700.0, 300.0  # submerged weights [N/m]
DIAMETER, RHO, G = 0.1, 1025.0, 9.81
DISPLACED = RHO * math.pi * DIAMETER ** 2 / 4  # displaced mass per m [kg/m]
ANCHOR = (-X0, 0.0, -DEPTH)
POINTS = 11


def expected_sections():
    """0-based section of each shape point from the fairlead, the upper
    section at a joint (none falls on the joint here)."""
    total = CHAIN + ROPE
    arcs = [total * (1 - k / (POINTS - 1)) for k in range(POINTS)]
    return [1 if arc >= CHAIN else 0 for arc in arcs]


def catenary(name, sections):
    rope = f"""
                section2.unstretchedLength {ROPE};
                section2.EA {EA};
                section2.weight {W_ROPE};""" if sections else ""
    return f"""
        {name}
        {{
            type fmuConnector;
            body hull;
            fmu "{fmu_path('catenary')}";
            report off;
            parameters
            {{
                unstretchedLength {CHAIN if sections else CHAIN + ROPE};
                EA {EA};
                weight {W_CHAIN};
                seabedContact 1;{rope}
                A.p (0 0 0);
                B.p {vec(ANCHOR)};
            }}
        }}
"""


def mooring_line(name):
    return f"""
        {name}
        {{
            type fmuConnector;
            body hull;
            fmu "{fmu_path('mooringLine')}";
            report off;
            parameters
            {{
                unstretchedLength {CHAIN};
                EA {EA};
                axialDamping 2e5;
                massPerLength {W_CHAIN / G + DISPLACED!r};
                diameter {DIAMETER};
                waterDensity {RHO};
                gravity {G};
                seabedContact 1;
                segments 14;
                section2.unstretchedLength {ROPE};
                section2.EA {EA};
                section2.axialDamping 2e5;
                section2.massPerLength {W_ROPE / G + DISPLACED!r};
                section2.diameter {DIAMETER};
                section2.segments 10;
                A.p (0 0 0);
                B.p {vec(ANCHOR)};
            }}
        }}
"""


MODEL = f"""
    solver {{ type Newmark; }}
    g (0 0 -9.81);
    bodies
    {{
{rigid_body("hull", 1e6, 1e6, (0, 0, 0), "Px")}
    }}
    restraints
    {{
{catenary("sections", True)}
{mooring_line("dynamic")}
{catenary("uniform", False)}
    }}
"""


def read_vtk(path, coordinates=None):
    """Points and point data fields of a legacy ASCII VTK polydata file;
    the points' coordinates (text) into the list coordinates when given."""
    with open(path) as f:
        words = f.read().split()
    points = int(words[words.index("POINTS") + 1])
    if coordinates is not None:
        start = words.index("POINTS") + 3
        coordinates += [words[start + 3 * i:start + 3 * i + 3] for i in range(points)]
    fields = {}
    i = 0
    while i < len(words):
        if words[i] == "SCALARS":
            name = words[i + 1]
            start = words.index("LOOKUP_TABLE", i) + 2
            fields[name] = [float(x) for x in words[start:start + points]]
            i = start + points
        else:
            i += 1
    return points, fields


def xyz_of(folder, name):
    coordinates = []
    read_vtk(os.path.join(folder, f"{name}_5.vtk"), coordinates)
    return coordinates


def main():
    case = Case("lineSections", MODEL, 0.1, 0.02)
    case.run()
    folder = os.path.join(case.dir, "VTK", "fmuConnectors")
    expected = expected_sections()
    failures = checks = 0
    for name in ("sections", "dynamic", "uniform"):
        points, fields = read_vtk(os.path.join(folder, f"{name}_5.vtk"))
        n = POINTS + (1 if name == "dynamic" else 0)
        checks += 1
        failures += check(f"{name}: {n} points with their tension",
                          points == n and len(fields.get("tension", [])) == n,
                          f"{points} points, fields {sorted(fields)}")
        section = fields.get("section")
        checks += 1
        if name == "uniform":
            failures += check(f"{name}: no section field", section is None,
                              f"fields {sorted(fields)}")
        else:
            failures += check(f"{name}: each point's section",
                              section == expected + [1] * (n - POINTS),
                              f"{section}, expected {expected} and 1 at a joint")
    # The joint of the dynamic line: the connector's outputs at the written
    # time, the same doubles (the VTK file at the case's writePrecision 17,
    # the .dat row in the shortest form that reads back: both exact)
    row = case.connector("dynamic")
    last = len(row["Time"]) - 1
    joint = [float(v) for v in xyz_of(folder, "dynamic")[POINTS]]
    outputs = [row[f"joint.{c}[1]"][last] for c in "xyz"]
    tension = read_vtk(os.path.join(folder, "dynamic_5.vtk"))[1]["tension"][POINTS]
    checks += 1
    failures += check("dynamic: the joint at joint.x/y/z[1], its tension section.lowerTension[2]",
                      row["Time"][last] == 0.1 and joint == outputs
                      and tension == row["section.lowerTension[2]"][last],
                      f"joint {joint}, outputs {outputs}; tension {tension}, "
                      f"section.lowerTension[2] {row['section.lowerTension[2]'][last]}")
    if not failures:
        case.cleanup()
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())

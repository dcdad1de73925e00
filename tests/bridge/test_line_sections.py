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


def read_vtk(path):
    """Points and point data fields of a legacy ASCII VTK polydata file."""
    with open(path) as f:
        words = f.read().split()
    points = int(words[words.index("POINTS") + 1])
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


def main():
    case = Case("lineSections", MODEL, 0.1, 0.02)
    case.run()
    folder = os.path.join(case.dir, "VTK", "fmuConnectors")
    expected = expected_sections()
    failures = checks = 0
    for name in ("sections", "dynamic", "uniform"):
        points, fields = read_vtk(os.path.join(folder, f"{name}_5.vtk"))
        checks += 1
        failures += check(f"{name}: {POINTS} points with their tension",
                          points == POINTS and len(fields.get("tension", [])) == POINTS,
                          f"{points} points, fields {sorted(fields)}")
        section = fields.get("section")
        checks += 1
        if name == "uniform":
            failures += check(f"{name}: no section field", section is None,
                              f"fields {sorted(fields)}")
        else:
            failures += check(f"{name}: each point's section",
                              section == expected,
                              f"{section}, expected {expected}")
    if not failures:
        case.cleanup()
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())

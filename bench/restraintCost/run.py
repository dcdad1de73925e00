"""Cost of one restraint evaluation: the linearSpring FMU through the
fmuConnector restraint against OpenFOAM's built-in linearSpring, measured
side by side in one run of restraintCost, printed as a ratio.

Run in the project's environment: tests/run-with-openfoam python3 bench/restraintCost/run.py
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "bridge"))
from bridgecase import Case, fmu_path, rigid_body, vec  # noqa: E402

MODEL = f"""
    solver {{ type symplectic; }}
    bodies
    {{
{rigid_body("hull", 2, 0.1, (0, 0, 0), "floating")}
    }}
    restraints
    {{
        builtin
        {{
            type linearSpring;
            body hull;
            anchor (0.3 0.2 1.2);
            refAttachmentPt (0.1 0 0.05);
            stiffness 50;
            damping 0.5;
            restLength 0.5;
        }}
        fmu
        {{
            type fmuConnector;
            body hull;
            fmu "{fmu_path('linearSpring')}";
            parameters
            {{
                stiffness 50;
                damping 0.5;
                restLength 0.5;
                A.p {vec((0.1, 0, 0.05))};
                B.p {vec((0.3, 0.2, 1.2))};
            }}
        }}
    }}
"""


def main():
    case = Case("restraintCost", MODEL, 1, 0.001)
    out = subprocess.run(
        ["restraintCost", "-case", case.dir, "-evaluations", "20000", "-rounds", "5"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, check=True,
    ).stdout
    case.cleanup()
    rows = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[0] in ("builtin", "fmu"):
            rows[parts[0]] = (float(parts[2]), float(parts[3]))
    b, f = rows["builtin"], rows["fmu"]
    print("Cost of one restraint evaluation (fastest of 5 rounds of 20000):")
    print(f"  built-in linearSpring          {b[0]:8.0f} ns (new step) {b[1]:8.0f} ns (repeated solve)")
    print(f"  linearSpring FMU (fmuConnector) {f[0]:8.0f} ns (new step) {f[1]:8.0f} ns (repeated solve)")
    print(f"  ratio FMU / built-in           {f[0] / b[0]:8.1f}            {f[1] / b[1]:8.1f}")
    print("A new step also writes the previous step's row of connector outputs to")
    print("postProcessing/fmuConnectors and saves the FMU state; a repeated solve")
    print("restores the state, steps the FMU and reads its outputs.")


if __name__ == "__main__":
    main()

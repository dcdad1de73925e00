#!/usr/bin/env python3
"""fmusim run on the Reference FMUs (FMI 3.0 co-simulation, built here from
their sources: third_party/referenceFmus/) against the results the
Reference FMUs ship (<model>/<model>_out.csv, their default experiment). Every difference is
one that third_party/referenceFmus/README.md explains; anything else fails:

- the numbers: the same doubles (each field read as a float), times and
  values, row for row;
- Booleans: fmusim writes 0 and 1 where the reference writes false and
  true;
- Feedthrough declares no step size: run with --step-size 0.1, the rows of
  its reference; its inputs (Feedthrough_in.csv) hold Int64 and UInt64
  extremes, beyond fmusim's Integer values (int): fmusim refuses the table
  naming the column, exit code 4 (its reference is the run without inputs);
- Stair asks to end the simulation at t = 9 (terminateSimulation with
  fmi3OK): fmusim stops there, exit code 0, as the reference does.

Usage: compareReference.py FMUSIM FMU_DIR SOURCE_DIR SCRATCH
"""
import csv
import os
import subprocess
import sys

FMUSIM, FMU_DIR, SOURCE, SCRATCH = sys.argv[1:5]

RUNS = {
    "BouncingBall": [],
    "Feedthrough": ["--step-size", "0.1"],
    "Stair": [],
    "VanDerPol": [],
}


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def value(text):
    """A field as the number it stands for; Booleans as 0 and 1; else text."""
    if text in ("false", "true"):
        return float(text == "true")
    try:
        return float(text)
    except ValueError:
        return text


def compare(model):
    out = os.path.join(SCRATCH, model + ".csv")
    done = subprocess.run([FMUSIM, "run", os.path.join(FMU_DIR, model + ".fmu"),
                           *RUNS[model], "--output-file", out],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return [f"fmusim exit {done.returncode}: {done.stderr.strip()}"]
    names, rows = read(out)
    ref_names, ref_rows = read(os.path.join(SOURCE, model, model + "_out.csv"))
    problems = []
    if names != ref_names:
        problems.append(f"columns {names}, the reference's {ref_names}")
    if len(rows) != len(ref_rows):
        problems.append(f"{len(rows)} rows, the reference's {len(ref_rows)}")
    booleans = set()
    for k, (row, ref) in enumerate(zip(rows, ref_rows)):
        for name, a, b in zip(names, row, ref):
            if b in ("false", "true"):
                booleans.add(name)
            if value(a) != value(b):
                problems.append(f"row {k + 1}, {name}: {a}, the reference's {b}")
                if len(problems) > 5:
                    return problems
    note = f" (Booleans {', '.join(sorted(booleans))} as 0/1)" if booleans else ""
    print(f"PASS {model}: {len(rows)} rows of {len(names) - 1} outputs, the "
          f"reference's numbers to the bit{note}"
          + (f"; {done.stderr.strip()}" if done.stderr.strip() else ""))
    return problems


def feedthrough_inputs():
    """Feedthrough_in.csv: refused by name, not wrapped."""
    done = subprocess.run([FMUSIM, "run", os.path.join(FMU_DIR, "Feedthrough.fmu"),
                           "--step-size", "0.1", "--input-file",
                           os.path.join(SOURCE, "Feedthrough", "Feedthrough_in.csv")],
                          capture_output=True, text=True)
    expected = "column 'Int64_input': -9.2233720368547758e+18 at t = 0 is beyond"
    if done.returncode != 4 or expected not in done.stderr:
        return [f"Feedthrough with Feedthrough_in.csv: exit {done.returncode}, "
                f"{done.stderr.strip()}"]
    print("PASS Feedthrough with Feedthrough_in.csv: refused, exit code 4: "
          + done.stderr.strip())
    return []


def main():
    os.makedirs(SCRATCH, exist_ok=True)
    failed = False
    for model in RUNS:
        for p in compare(model):
            print(f"FAIL {model}: {p}")
            failed = True
    for p in feedthrough_inputs():
        print(f"FAIL {p}")
        failed = True
    if failed:
        sys.exit(1)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Every connector's FMI 3.0 FMU gives, in fmusim, the bits of its FMI 2.0
FMU for the same inputs:

- fmusim run, the inputs from one table (the kinematics moving about their
  start values, with rotations), every output: the same text, number for
  number (17 significant digits: the same doubles), in both isolations;
- fmusim twobody, explicit and implicit (the state restored before every
  repeated step): the same text;
- fmusim check says of the 3.0 FMU what it says of the 2.0 one, word for
  word (the lines' weight makes equal-and-opposite-forces fail for both).

Columns are matched by name: the 3.0 FMU's elements have the 2.0 FMU's
names (docs/connector-fmu-interface.md, FMI 3.0), a line's points too
(shape.x/y/z[i]).

Usage: sameAnswers.py FMUSIM FMU_DIR SCRATCH

tests/customConnector/test_bungee3.py imports it (set FMUSIM first) to
compare the example's two bungees the same way.
"""
import csv
import io
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
import zipfile

FMUSIM = FMU_DIR = SCRATCH = None   # sys.argv[1:4] when run as a script


def fmusim(*args):
    done = subprocess.run([FMUSIM, *args], capture_output=True, text=True)
    if done.returncode != 0:
        raise AssertionError(f"fmusim {' '.join(args)}: exit {done.returncode}\n"
                             f"{done.stderr}")
    return done.stdout


def inputs_of(fmu2):
    """{name: start} of the 2.0 FMU's Real inputs."""
    with zipfile.ZipFile(fmu2) as z:
        root = ET.fromstring(z.read("modelDescription.xml"))
    found = {}
    for v in root.iter("ScalarVariable"):
        real = v.find("Real")
        if v.get("causality") == "input" and real is not None:
            found[v.get("name")] = float(real.get("start", "0"))
    return found


def rotation(angle, axis):
    c, s = math.cos(angle), math.sin(angle)
    i, j = [(1, 2), (0, 2), (0, 1)][axis]
    R = [[1.0 if a == b else 0.0 for b in range(3)] for a in range(3)]
    R[i][i], R[i][j], R[j][i], R[j][j] = c, -s, s, c
    return R


def input_table(inputs, path):
    """The kinematics about their start values: small motions, rotations
    about a body's own axis, other inputs at their start values."""
    names = sorted(inputs)
    rows = []
    for k in range(21):
        t = 0.005 * k
        row = [t]
        for name in names:
            value = inputs[name]
            m = re.match(r"([AB])\.(r|v|omega)\[(\d)\]$", name)
            R = re.match(r"([AB])\.R\[(\d),(\d)\]$", name)
            if m:
                body, what, i = m.group(1), m.group(2), int(m.group(3))
                phase = (0 if body == "A" else 1.3) + 0.7 * i
                value += {"r": 0.01, "v": 0.05, "omega": 0.2}[what] * math.sin(
                    40 * t + phase)
            elif R:
                body, i, j = R.group(1), int(R.group(2)), int(R.group(3))
                axis = 2 if body == "A" else 0
                value = rotation(0.1 * math.sin(30 * t), axis)[i - 1][j - 1]
            row.append(value)
        rows.append(row)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time", *names])
        for row in rows:
            w.writerow([repr(x) for x in row])


def same(text3, text2, what):
    t3 = list(csv.reader(io.StringIO(text3)))
    t2 = list(csv.reader(io.StringIO(text2)))
    header3 = t3[0]
    if sorted(header3) != sorted(t2[0]):
        raise AssertionError(f"{what}: the columns differ:\n{header3}\n{t2[0]}")
    if len(t3) != len(t2):
        raise AssertionError(f"{what}: {len(t3)} rows, 2.0: {len(t2)}")
    where = [header3.index(n) for n in t2[0]]
    for k, (r3, r2) in enumerate(zip(t3[1:], t2[1:])):
        for c, n in enumerate(t2[0]):
            if r3[where[c]] != r2[c]:
                raise AssertionError(f"{what}: row {k + 1}, {n}: "
                                     f"{r3[where[c]]} (3.0) {r2[c]} (2.0)")
    return len(t2) - 1, len(t2[0]) - 1


def main():
    os.makedirs(SCRATCH, exist_ok=True)
    names = sorted(f[:-4] for f in os.listdir(os.path.join(FMU_DIR, "fmi3"))
                   if f.endswith(".fmu"))
    if not names:
        raise AssertionError(f"no FMI 3.0 FMU in {FMU_DIR}/fmi3")
    failed = []
    for name in names:
        fmu2 = os.path.join(FMU_DIR, name + ".fmu")
        fmu3 = os.path.join(FMU_DIR, "fmi3", name + ".fmu")
        try:
            table = os.path.join(SCRATCH, name + "-inputs.csv")
            input_table(inputs_of(fmu2), table)
            for isolation in ("none", "process"):
                run = ["run", "--stop-time", "0.1", "--step-size", "0.005",
                       "--input-file", table, "--isolation", isolation]
                rows, cols = same(fmusim(*run, fmu3), fmusim(*run, fmu2),
                                  f"{name} run ({isolation})")
            print(f"PASS {name} run: {rows} rows of {cols} outputs, both isolations")
            two = inputs_of(fmu2).keys() >= {"B.r[1]"}
            for scheme in ("explicit", "implicit"):
                args = ["twobody", "--stop-time", "0.05", "--scheme", scheme,
                        "--A.velocity", "0.1 0 0.05", "--A.angular-velocity", "0 0.3 0.1"]
                if two:
                    args += ["--B.position", "0.2 0.1 0", "--B.velocity", "-0.05 0.02 0"]
                rows, cols = same(fmusim(*args, fmu3), fmusim(*args, fmu2),
                                  f"{name} twobody {scheme}")
                print(f"PASS {name} twobody {scheme}: {rows} rows of {cols} columns")
            def check(fmu):
                done = subprocess.run([FMUSIM, "check", fmu], capture_output=True,
                                      text=True)
                return done.returncode, done.stdout
            report = check(fmu3)
            if report != check(fmu2) or report[0] not in (0, 1):
                raise AssertionError(f"{name}: fmusim check of the 3.0 FMU:\n"
                                     f"{report[1]}\nof the 2.0 FMU:\n{check(fmu2)[1]}")
            report = report[1]
            print(f"PASS {name} check: {report.strip().splitlines()[-1]}")
        except AssertionError as e:
            print(f"FAIL {e}")
            failed.append(name)
    if failed:
        sys.exit(f"the FMI 3.0 FMUs of {', '.join(failed)} differ from their 2.0 FMUs")


if __name__ == "__main__":
    FMUSIM, FMU_DIR, SCRATCH = sys.argv[1:4]
    main()

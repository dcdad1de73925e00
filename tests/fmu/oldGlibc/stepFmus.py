"""Load, instantiate, initialize, step and free FMI 2.0 and FMI 3.0
co-simulation FMUs through their C API alone (ctypes), as any FMI tool
would, with nothing of the project but this file and its modules beside it
(fmucalls.py: the C API; fmudescription.py: modelDescription.xml;
fmucompare.py: the comparisons): they run in the Debian 11 root of
runInDebian11.sh with that root's python3 and glibc.

    python3 stepFmus.py [options] model.fmu...

    --output FILE          the outputs of every step as JSON
    --reference FILE       fail unless the outputs agree with those of FILE
                           (the same FMUs stepped on another system) to
                           RTOL of each output's scale (see compare)
    --expect-glibc 2.xx    fail unless the process runs on that glibc
    --set MODEL:NAME=VALUE start value of variable NAME of the FMU whose
                           modelIdentifier is MODEL (repeatable)
    --same-versions        fail unless the FMI 2.0 and 3.0 FMUs of one
                           modelIdentifier, both given, give bitwise the
                           same outputs (see compare_versions)

The archive's fmiVersion picks the API; a 3.0 FMU's results are named
fmi3/<modelIdentifier>. The GUID (instantiationToken), the
value references and the start values come from each FMU's
modelDescription.xml. A 3.0 FMU's arrays (Dimension elements: a start, or
a structural parameter's valueReference) are taken apart into elements
under FMI 2.0's names (docs/connector-fmu-interface.md, "FMI 3.0"): B.r[2]
is element 2 of the 3-array B.r, A.R[1,2] element 2 of the 3 x 3 array
A.R (row-major), shape.x[i] element i of the 11-array shape.x; an array is set and got
whole. After initialization body B moves away from its start position with
velocity U_B (m/s) and both bodies turn, for STEPS steps of H seconds; the
inputs are set to their values at t + h before the step from t to t + h
(fmi3DoStep without event mode or early return), then every Real (Float64)
output is read and must be finite. Any status other than OK fails, with
the FMU's log messages printed. Python 3.9 or later (Debian 11's); x86-64
Linux (binaries/linux64, binaries/x86_64-linux).
"""
import argparse
import json
import math
import os
import shutil
import sys
import tempfile
import zipfile

from fmucalls import Failure, Fmu, glibc_version, loaded_objects
from fmucompare import RTOL, compare, compare_versions
from fmudescription import Description

STEPS = 20
H = 0.01
U_B = (0.4, 0.3, -0.2)  # m/s, added to B.r and B.v
OMEGA = {"A.omega[1]": -0.1, "B.omega[3]": 0.5}  # rad/s, added to the start
FOREIGN = ("libstdc++", "libsundials")  # what an FMU carries inside


def inputs_at(t, elements):
    """{element name: value} of the moving inputs at time t."""
    values = {}
    for i, u in enumerate(U_B):
        for name, value in ((f"B.r[{i + 1}]", u * t), (f"B.v[{i + 1}]", u)):
            if name in elements and elements[name][1] == "input":
                values[name] = elements[name][2] + value
    for name, omega in OMEGA.items():
        if name in elements and elements[name][1] == "input":
            values[name] = elements[name][2] + omega
    return values


def step_fmu(path, starts):
    """(modelIdentifier, FMI version, the Real outputs after every step:
    {2.0 name: [value per step]}) of the FMU at path."""
    folder = tempfile.mkdtemp(prefix="stepFmus.")
    try:
        with zipfile.ZipFile(path) as archive:
            archive.extractall(folder)
        description = Description(folder)
        identifier, elements = description.identifier, description.elements
        unknown = set(starts.get(identifier, {})) - set(elements)
        if unknown:
            raise Failure(f"--set names no Real variable of {identifier}: {', '.join(sorted(unknown))}")
        for name, value in starts.get(identifier, {}).items():
            reference, causality, _, offset = elements[name]
            elements[name] = (reference, causality, value, offset)
        current = {name: element[2] for name, element in elements.items()}
        outputs = sorted((n for n, v in elements.items() if v[1] == "output"),
                         key=lambda n: elements[n][0::3])
        if not outputs:
            raise Failure("no Real output in modelDescription.xml")
        before = set(loaded_objects())
        fmu = Fmu(folder, description)
        brought = [os.path.basename(n) for n in loaded_objects() if n not in before]
        print(f"  {identifier} (FMI {description.version}.0): loaded with {' '.join(brought)}")
        foreign = [n for n in brought if n.startswith(FOREIGN)]
        if foreign:
            raise Failure(f"it brought {' '.join(foreign)}: an FMU must carry it inside")
        fmu.instantiate(os.path.join(folder, "resources"))
        fmu.set_real(starts.get(identifier, {}), current)
        fmu.enter_initialization()
        fmu.set_real(inputs_at(0.0, elements), current)
        fmu.call("ExitInitializationMode")
        refs = sorted({elements[n][0] for n in outputs})
        history = {n: [] for n in outputs}
        for k in range(STEPS):
            t = k * H
            fmu.set_real(inputs_at(t + H, elements), current)
            fmu.do_step(t, H)
            arrays = dict(zip(refs, fmu.get_real(refs)))
            for name in outputs:
                value = arrays[elements[name][0]][elements[name][3]]
                if not math.isfinite(value):
                    raise Failure(f"{name} = {value} after the step at t = {t}")
                history[name].append(value)
        fmu.free()
        print(f"  {identifier} (FMI {description.version}.0): {STEPS} steps, "
              f"{len(outputs)} outputs finite, {outputs[0]} = {history[outputs[0]][-1]:.6g}")
        return identifier, description.version, history
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("fmus", nargs="+")
    parser.add_argument("--output")
    parser.add_argument("--reference")
    parser.add_argument("--expect-glibc")
    parser.add_argument("--set", action="append", default=[], metavar="MODEL:NAME=VALUE")
    parser.add_argument("--same-versions", action="store_true")
    args = parser.parse_args()

    starts = {}
    for setting in args.set:
        model, _, assignment = setting.partition(":")
        name, _, value = assignment.partition("=")
        if not model or not name or not value:
            parser.error(f"--set {setting}: expected MODEL:NAME=VALUE")
        starts.setdefault(model, {})[name] = float(value)

    version = glibc_version()
    print(f"stepFmus.py: Python {sys.version.split()[0]}, glibc {version}")
    if args.expect_glibc and version != args.expect_glibc:
        print(f"stepFmus.py: runs on glibc {version}, expected {args.expect_glibc}")
        return 1

    results, failed = {}, []
    for path in args.fmus:
        try:
            identifier, fmi_version, history = step_fmu(path, starts)
            results[identifier if fmi_version == "2" else "fmi3/" + identifier] = history
        except Failure as error:
            print(f"  {os.path.basename(path)}: FAILED: {error}")
            failed.append(os.path.basename(path))
    if args.output:
        with open(args.output, "w") as stream:
            json.dump(results, stream)
    if args.same_versions and not failed:
        summary, failures = compare_versions(results)
        if not summary and not failures:
            failures = ["no modelIdentifier with both an FMI 2.0 and an FMI 3.0 FMU"]
        print("stepFmus.py: the FMI 3.0 FMUs against the FMI 2.0 ones:\n  "
              + "\n  ".join(summary or ["none"]))
        if failures:
            print("stepFmus.py: the FMI versions differ:\n  " + "\n  ".join(failures))
            failed.append("same-versions")
    if args.reference and not failed:
        with open(args.reference) as stream:
            summary, failures = compare(results, json.load(stream))
        print(f"stepFmus.py: the outputs against {args.reference}'s:\n  " + "\n  ".join(summary))
        if failures:
            print(f"stepFmus.py: outputs differ by more than {RTOL:g}:\n  " + "\n  ".join(failures))
            failed.append("reference")
    if failed:
        print(f"stepFmus.py: FAILED: {', '.join(failed)}")
        return 1
    print(f"stepFmus.py: {len(results)} FMUs loaded, stepped and freed on glibc {version}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

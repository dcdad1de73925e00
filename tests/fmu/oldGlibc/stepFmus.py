"""Load, instantiate, initialize, step and free FMI 2.0 co-simulation FMUs
through their C API alone (ctypes), as any FMI tool would, with nothing of
the project but this file: it runs in the Debian 11 root of
runInDebian11.sh with that root's python3 and glibc.

    python3 stepFmus.py [options] model.fmu...

    --output FILE          the outputs of every step as JSON
    --reference FILE       fail unless the outputs agree with those of FILE
                           (the same FMUs stepped on another system) to
                           RTOL of each output's scale (see compare)
    --expect-glibc 2.xx    fail unless the process runs on that glibc
    --set MODEL:NAME=VALUE start value of variable NAME of the FMU whose
                           modelIdentifier is MODEL (repeatable)

The GUID, the value references and the start values come from each FMU's
modelDescription.xml. After initialization body B moves away from its
start position with velocity U_B (m/s) and both bodies turn, for STEPS
steps of H seconds; the inputs are set to their values at t + h before
fmi2DoStep(t, h), then every Real output is read and must be finite.
Any status other than fmi2OK fails, with the FMU's log messages printed.
Python 3.9 or later (Debian 11's); x86-64 Linux (binaries/linux64).
"""
import argparse
import ctypes
import json
import math
import os
import pathlib
import shutil
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile

import _ctypes

STEPS = 20
H = 0.01
U_B = (0.4, 0.3, -0.2)  # m/s, added to B.r and B.v
OMEGA = {"A.omega[1]": -0.1, "B.omega[3]": 0.5}  # rad/s, added to the start
RTOL = 1e-9  # --reference: agreement, relative to an output's scale

FMI2_OK = 0
FMI2_CO_SIMULATION = 1
STATUS = ("fmi2OK", "fmi2Warning", "fmi2Discard", "fmi2Error", "fmi2Fatal", "fmi2Pending")
FOREIGN = ("libstdc++", "libsundials")  # what an FMU carries inside

# fmi2CallbackLogger is variadic; on x86-64 its first variadic argument
# arrives as a sixth one would, which is all a "%s" message needs.
LOGGER = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int,
                          ctypes.c_char_p, ctypes.c_char_p, ctypes.c_void_p)


class Callbacks(ctypes.Structure):
    _fields_ = [("logger", LOGGER), ("allocateMemory", ctypes.c_void_p),
                ("freeMemory", ctypes.c_void_p), ("stepFinished", ctypes.c_void_p),
                ("componentEnvironment", ctypes.c_void_p)]


class Failure(Exception):
    pass


def status_name(status):
    return STATUS[status] if 0 <= status < len(STATUS) else str(status)


def libc():
    return ctypes.CDLL("libc.so.6")


def glibc_version():
    get = libc().gnu_get_libc_version
    get.restype = ctypes.c_char_p
    return get().decode()


def loaded_objects():
    """Paths of the shared objects in the process (dl_iterate_phdr)."""
    names = []

    class PhdrInfo(ctypes.Structure):
        _fields_ = [("addr", ctypes.c_void_p), ("name", ctypes.c_char_p)]

    @ctypes.CFUNCTYPE(ctypes.c_int, ctypes.POINTER(PhdrInfo), ctypes.c_size_t, ctypes.c_void_p)
    def collect(info, size, data):
        if info.contents.name:
            names.append(info.contents.name.decode())
        return 0

    libc().dl_iterate_phdr(collect, None)
    return names


def model_description(folder):
    """(modelIdentifier, guid, {name: (valueReference, causality, start)})
    of the Real variables."""
    root = ET.parse(os.path.join(folder, "modelDescription.xml")).getroot()
    cs = root.find("CoSimulation")
    if cs is None:
        raise Failure("no <CoSimulation> in modelDescription.xml")
    variables = {}
    for v in root.find("ModelVariables"):
        real = v.find("Real")
        if real is not None:
            start = real.get("start")
            variables[v.get("name")] = (int(v.get("valueReference")), v.get("causality"),
                                        None if start is None else float(start))
    return cs.get("modelIdentifier"), root.get("guid"), variables


def inputs_at(t, variables):
    """{valueReference: value} of the moving inputs at time t."""
    values = {}
    for i, u in enumerate(U_B):
        for name, value in ((f"B.r[{i + 1}]", u * t), (f"B.v[{i + 1}]", u)):
            if name in variables and variables[name][1] == "input":
                values[variables[name][0]] = variables[name][2] + value
    for name, omega in OMEGA.items():
        if name in variables and variables[name][1] == "input":
            values[variables[name][0]] = variables[name][2] + omega
    return values


class Fmu:
    """One FMU's binary, loaded from its unpacked folder."""

    def __init__(self, folder, identifier):
        path = os.path.join(folder, "binaries", "linux64", identifier + ".so")
        try:
            self.lib = ctypes.CDLL(path)
        except OSError as error:
            raise Failure(f"dlopen failed: {error}")
        self.messages = []
        self.logger = LOGGER(self.log)
        self.callbacks = Callbacks(self.logger, ctypes.cast(libc().calloc, ctypes.c_void_p),
                                   ctypes.cast(libc().free, ctypes.c_void_p), None, None)
        self.lib.fmi2Instantiate.restype = ctypes.c_void_p
        self.lib.fmi2Instantiate.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                                             ctypes.c_char_p, ctypes.POINTER(Callbacks),
                                             ctypes.c_int, ctypes.c_int]
        self.lib.fmi2SetupExperiment.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_double,
                                                 ctypes.c_double, ctypes.c_int, ctypes.c_double]
        self.lib.fmi2DoStep.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double,
                                        ctypes.c_int]
        for name in ("fmi2SetReal", "fmi2GetReal"):
            getattr(self.lib, name).argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_uint),
                                                ctypes.c_size_t, ctypes.POINTER(ctypes.c_double)]
        for name in ("fmi2EnterInitializationMode", "fmi2ExitInitializationMode",
                     "fmi2Terminate", "fmi2FreeInstance"):
            getattr(self.lib, name).argtypes = [ctypes.c_void_p]
        self.lib.fmi2FreeInstance.restype = None

    def log(self, environment, instance, status, category, message, argument):
        text = (message or b"").decode(errors="replace")
        if text.count("%") == 1 and "%s" in text and argument:
            text = text.replace("%s", ctypes.string_at(argument).decode(errors="replace"))
        self.messages.append(f"[{status_name(status)}] {text}")

    def call(self, name, *args):
        status = getattr(self.lib, name)(*args)
        if status != FMI2_OK:
            log = "".join("\n    " + m for m in self.messages) or " (nothing logged)"
            raise Failure(f"{name} returned {status_name(status)}; the FMU's log:{log}")

    def set_real(self, component, values):
        if values:
            refs = (ctypes.c_uint * len(values))(*values.keys())
            data = (ctypes.c_double * len(values))(*values.values())
            self.call("fmi2SetReal", component, refs, len(values), data)

    def get_real(self, component, refs):
        data = (ctypes.c_double * len(refs))()
        self.call("fmi2GetReal", component, (ctypes.c_uint * len(refs))(*refs), len(refs), data)
        return list(data)

    def unload(self):
        _ctypes.dlclose(self.lib._handle)
        self.lib = None


def step_fmu(path, starts):
    """(modelIdentifier, the Real outputs after every step: {name: [value
    per step]}) of the FMU at path."""
    folder = tempfile.mkdtemp(prefix="stepFmus.")
    try:
        with zipfile.ZipFile(path) as archive:
            archive.extractall(folder)
        identifier, guid, variables = model_description(folder)
        unknown = set(starts.get(identifier, {})) - set(variables)
        if unknown:
            raise Failure(f"--set names no Real variable of {identifier}: {', '.join(sorted(unknown))}")
        for name, value in starts.get(identifier, {}).items():
            reference, causality, _ = variables[name]
            variables[name] = (reference, causality, value)
        outputs = sorted((n for n, v in variables.items() if v[1] == "output"),
                         key=lambda n: variables[n][0])
        if not outputs:
            raise Failure("no Real output in modelDescription.xml")
        before = set(loaded_objects())
        fmu = Fmu(folder, identifier)
        brought = [os.path.basename(n) for n in loaded_objects() if n not in before]
        print(f"  {identifier}: loaded with {' '.join(brought)}")
        foreign = [n for n in brought if n.startswith(FOREIGN)]
        if foreign:
            raise Failure(f"it brought {' '.join(foreign)}: an FMU must carry it inside")
        resources = pathlib.Path(folder, "resources").as_uri().encode()
        component = fmu.lib.fmi2Instantiate(identifier.encode(), FMI2_CO_SIMULATION,
                                            guid.encode(), resources,
                                            ctypes.byref(fmu.callbacks), 0, 0)
        if not component:
            raise Failure("fmi2Instantiate returned NULL: " + "; ".join(fmu.messages))
        fmu.set_real(component, {variables[n][0]: v for n, v in starts.get(identifier, {}).items()})
        fmu.call("fmi2SetupExperiment", component, 0, 0.0, 0.0, 0, 0.0)
        fmu.call("fmi2EnterInitializationMode", component)
        fmu.set_real(component, inputs_at(0.0, variables))
        fmu.call("fmi2ExitInitializationMode", component)
        refs = [variables[n][0] for n in outputs]
        history = {n: [] for n in outputs}
        for k in range(STEPS):
            t = k * H
            fmu.set_real(component, inputs_at(t + H, variables))
            fmu.call("fmi2DoStep", component, t, H, 1)
            for name, value in zip(outputs, fmu.get_real(component, refs)):
                if not math.isfinite(value):
                    raise Failure(f"{name} = {value} after the step at t = {t}")
                history[name].append(value)
        fmu.call("fmi2Terminate", component)
        fmu.lib.fmi2FreeInstance(component)
        fmu.unload()
        print(f"  {identifier}: {STEPS} steps, {len(outputs)} outputs finite, "
              f"{outputs[0]} = {history[outputs[0]][-1]:.6g}")
        return identifier, history
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def compare(results, reference):
    """(summary per FMU, failures) of two runs' outputs. An output agrees
    when every step's value is within RTOL times the largest magnitude it
    takes in the run, or than 1 (SI units) for an output that stays near
    zero: glibc's libm differs between versions in the last bit of some
    functions (hypot, asinh, tanh, atan2 between 2.31 and 2.36), which the
    dynamic line's integrator carries on."""
    summary, failures = [], []
    for identifier in sorted(set(results) | set(reference)):
        ours, theirs = results.get(identifier), reference.get(identifier)
        if ours is None or theirs is None or set(ours) != set(theirs):
            failures.append(f"{identifier}: not the same outputs in the two runs")
            continue
        worst, identical = 0.0, 0
        for name in sorted(ours):
            a, b = ours[name], theirs[name]
            if len(a) != len(b):
                failures.append(f"{identifier}.{name}: {len(a)} steps against {len(b)}")
                continue
            identical += a == b
            scale = max(max(map(abs, a + b)), 1.0)
            for k, (x, y) in enumerate(zip(a, b)):
                difference = abs(x - y) / scale
                worst = max(worst, difference)
                if difference > RTOL:
                    failures.append(f"{identifier}.{name}: step {k + 1}: {x!r} against {y!r}")
                    break
        summary.append(f"{identifier}: {identical} of {len(ours)} outputs bit-identical, "
                       f"the largest difference {worst:.2g} of an output's scale")
    return summary, failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("fmus", nargs="+")
    parser.add_argument("--output")
    parser.add_argument("--reference")
    parser.add_argument("--expect-glibc")
    parser.add_argument("--set", action="append", default=[], metavar="MODEL:NAME=VALUE")
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
            identifier, history = step_fmu(path, starts)
            results[identifier] = history
        except Failure as error:
            print(f"  {os.path.basename(path)}: FAILED: {error}")
            failed.append(os.path.basename(path))
    if args.output:
        with open(args.output, "w") as stream:
            json.dump(results, stream)
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

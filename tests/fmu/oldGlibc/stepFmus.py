"""Load, instantiate, initialize, step and free FMI 2.0 and FMI 3.0
co-simulation FMUs through their C API alone (ctypes), as any FMI tool
would, with nothing of the project but this file: it runs in the Debian 11
root of runInDebian11.sh with that root's python3 and glibc.

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
A.R (row-major), shape[i,1] is 2.0's shape.x[i]; an array is set and got
whole. After initialization body B moves away from its start position with
velocity U_B (m/s) and both bodies turn, for STEPS steps of H seconds; the
inputs are set to their values at t + h before the step from t to t + h
(fmi3DoStep without event mode or early return), then every Real (Float64)
output is read and must be finite. Any status other than OK fails, with
the FMU's log messages printed. Python 3.9 or later (Debian 11's); x86-64
Linux (binaries/linux64, binaries/x86_64-linux).
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

OK = 0  # fmi2OK, fmi3OK
FMI2_CO_SIMULATION = 1
STATUS = ("OK", "Warning", "Discard", "Error", "Fatal", "Pending")  # fmi2OK, fmi3OK, ...
FOREIGN = ("libstdc++", "libsundials")  # what an FMU carries inside

# fmi2CallbackLogger is variadic; on x86-64 its first variadic argument
# arrives as a sixth one would, which is all a "%s" message needs.
LOGGER = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int,
                          ctypes.c_char_p, ctypes.c_char_p, ctypes.c_void_p)
# fmi3LogMessageCallback: the message comes formatted
LOGGER3 = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int, ctypes.c_char_p,
                           ctypes.c_char_p)


class Callbacks(ctypes.Structure):
    _fields_ = [("logger", LOGGER), ("allocateMemory", ctypes.c_void_p),
                ("freeMemory", ctypes.c_void_p), ("stepFinished", ctypes.c_void_p),
                ("componentEnvironment", ctypes.c_void_p)]


class Failure(Exception):
    pass


def status_name(status, version="2"):
    prefix = "fmi" + version
    return prefix + STATUS[status] if 0 <= status < len(STATUS) else str(status)


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


def element_names(name, dimensions):
    """FMI 2.0's names of the elements of a 3.0 array, row-major."""
    names = [name]
    for n in dimensions:
        names = [f"{base}{',' if '[' in base else '['}{i}" for base in names
                 for i in range(1, n + 1)]
    return [n + "]" for n in names] if dimensions else names


class Description:
    """What a run needs of modelDescription.xml: version ("2" or "3"),
    identifier, token (GUID or instantiationToken), sizes {valueReference:
    elements of its array (1 for a scalar)} and elements {2.0 name:
    (valueReference, causality, start, offset in its array)} of the Real
    (Float64) variables."""

    def __init__(self, folder):
        root = ET.parse(os.path.join(folder, "modelDescription.xml")).getroot()
        self.version = root.get("fmiVersion", "")[:1]
        if self.version not in ("2", "3"):
            raise Failure(f"fmiVersion {root.get('fmiVersion')!r}: neither 2.0 nor 3.0")
        cs = root.find("CoSimulation")
        if cs is None:
            raise Failure("no <CoSimulation> in modelDescription.xml")
        self.identifier = cs.get("modelIdentifier")
        self.token = root.get("guid" if self.version == "2" else "instantiationToken")
        self.sizes, self.elements = {}, {}
        variables = root.find("ModelVariables")
        if self.version == "2":
            for v in variables:
                real = v.find("Real")
                if real is not None:
                    self.add(v.get("name"), [], v.get("valueReference"), v.get("causality"),
                             real.get("start"))
            return
        structural = {v.get("valueReference"): v.get("start") for v in variables}
        for v in variables:
            if v.tag != "Float64":
                continue
            dimensions = []
            for d in v.findall("Dimension"):
                start = d.get("start") or structural.get(d.get("valueReference"))
                if start is None:
                    raise Failure(f"{v.get('name')}: a Dimension without start or a known "
                                  f"structural parameter (valueReference {d.get('valueReference')})")
                dimensions.append(int(start))
            self.add(v.get("name"), dimensions, v.get("valueReference"), v.get("causality"),
                     v.get("start"))

    def add(self, name, dimensions, reference, causality, start):
        names = element_names(name, dimensions)
        starts = [None] * len(names) if start is None else [float(x) for x in start.split()]
        if len(starts) != len(names):
            raise Failure(f"{name}: {len(starts)} start values for {len(names)} elements")
        reference = int(reference)
        self.sizes[reference] = len(names)
        for offset, (element, value) in enumerate(zip(names, starts)):
            self.elements[element] = (reference, causality, value, offset)


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


class Fmu:
    """One FMU's binary, loaded from its unpacked folder, and its instance:
    the calls of FMI 2.0 or 3.0 (description.version)."""

    def __init__(self, folder, description):
        self.description = description
        self.version = description.version
        self.fmi = "fmi" + self.version
        platform = "linux64" if self.version == "2" else "x86_64-linux"
        path = os.path.join(folder, "binaries", platform, description.identifier + ".so")
        try:
            self.lib = ctypes.CDLL(path)
        except OSError as error:
            raise Failure(f"dlopen failed: {error}")
        self.messages = []
        self.component = None
        handle = ctypes.c_void_p
        real = ctypes.POINTER(ctypes.c_double)
        if self.version == "2":
            self.logger = LOGGER(self.log)
            self.callbacks = Callbacks(self.logger, ctypes.cast(libc().calloc, handle),
                                       ctypes.cast(libc().free, handle), None, None)
            self.lib.fmi2Instantiate.restype = handle
            self.lib.fmi2Instantiate.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                                                 ctypes.c_char_p, ctypes.POINTER(Callbacks),
                                                 ctypes.c_int, ctypes.c_int]
            self.lib.fmi2SetupExperiment.argtypes = [handle, ctypes.c_int, ctypes.c_double,
                                                     ctypes.c_double, ctypes.c_int,
                                                     ctypes.c_double]
            self.lib.fmi2EnterInitializationMode.argtypes = [handle]
            self.lib.fmi2DoStep.argtypes = [handle, ctypes.c_double, ctypes.c_double,
                                            ctypes.c_int]
            values = [handle, ctypes.POINTER(ctypes.c_uint), ctypes.c_size_t, real]
        else:
            flag = ctypes.c_bool
            self.logger = LOGGER3(self.log3)
            self.lib.fmi3InstantiateCoSimulation.restype = handle
            self.lib.fmi3InstantiateCoSimulation.argtypes = [
                ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, flag, flag, flag, flag,
                ctypes.POINTER(ctypes.c_uint32), ctypes.c_size_t, handle, LOGGER3, handle]
            self.lib.fmi3EnterInitializationMode.argtypes = [handle, flag, ctypes.c_double,
                                                             ctypes.c_double, flag,
                                                             ctypes.c_double]
            self.lib.fmi3DoStep.argtypes = [handle, ctypes.c_double, ctypes.c_double, flag,
                                            ctypes.POINTER(flag), ctypes.POINTER(flag),
                                            ctypes.POINTER(flag), real]
            values = [handle, ctypes.POINTER(ctypes.c_uint32), ctypes.c_size_t, real,
                      ctypes.c_size_t]
        self.set_name, self.get_name = ("SetReal", "GetReal") if self.version == "2" \
            else ("SetFloat64", "GetFloat64")
        for name in (self.set_name, self.get_name):
            getattr(self.lib, self.fmi + name).argtypes = values
        for name in ("ExitInitializationMode", "Terminate", "FreeInstance"):
            getattr(self.lib, self.fmi + name).argtypes = [handle]
        getattr(self.lib, self.fmi + "FreeInstance").restype = None

    def log(self, environment, instance, status, category, message, argument):
        text = (message or b"").decode(errors="replace")
        if text.count("%") == 1 and "%s" in text and argument:
            text = text.replace("%s", ctypes.string_at(argument).decode(errors="replace"))
        self.messages.append(f"[{status_name(status)}] {text}")

    def log3(self, environment, status, category, message):
        text = (message or b"").decode(errors="replace")
        self.messages.append(f"[{status_name(status, '3')}] {text}")

    def call(self, name, *args):
        status = getattr(self.lib, self.fmi + name)(self.component, *args)
        if status != OK:
            log = "".join("\n    " + m for m in self.messages) or " (nothing logged)"
            raise Failure(f"{self.fmi}{name} returned {status_name(status, self.version)}; "
                          f"the FMU's log:{log}")

    def instantiate(self, resources):
        if self.version == "2":
            self.component = self.lib.fmi2Instantiate(
                self.description.identifier.encode(), FMI2_CO_SIMULATION,
                self.description.token.encode(), pathlib.Path(resources).as_uri().encode(),
                ctypes.byref(self.callbacks), 0, 0)
        else:
            self.component = self.lib.fmi3InstantiateCoSimulation(
                self.description.identifier.encode(), self.description.token.encode(),
                (resources + os.sep).encode(), False, False, False, False, None, 0, None,
                self.logger, None)
        if not self.component:
            raise Failure(f"{self.fmi}Instantiate returned NULL: " + "; ".join(self.messages))

    def enter_initialization(self):
        if self.version == "2":
            self.call("SetupExperiment", 0, 0.0, 0.0, 0, 0.0)
            self.call("EnterInitializationMode")
        else:
            self.call("EnterInitializationMode", False, 0.0, 0.0, False, 0.0)

    def do_step(self, t, h):
        if self.version == "2":
            self.call("DoStep", t, h, 1)
            return
        event, terminate, early = ctypes.c_bool(), ctypes.c_bool(), ctypes.c_bool()
        reached = ctypes.c_double()
        self.call("DoStep", t, h, True, ctypes.byref(event), ctypes.byref(terminate),
                  ctypes.byref(early), ctypes.byref(reached))
        if event.value or terminate.value or early.value or reached.value != t + h:
            raise Failure(f"fmi3DoStep at t = {t}: eventHandlingNeeded {event.value}, "
                          f"terminateSimulation {terminate.value}, earlyReturn {early.value}, "
                          f"lastSuccessfulTime {reached.value!r} (expected {t + h!r})")

    def transfer(self, name, refs, data):
        """fmiXSetReal or fmiXGetReal of the whole arrays refs into or from
        data; 3.0 also takes the number of elements."""
        extra = () if self.version == "2" else (len(data),)
        self.call(name, (ctypes.c_uint * len(refs))(*refs), len(refs), data, *extra)

    def set_real(self, values, current):
        """Sets the elements {name: value}, each with its whole array, the
        other elements of which take their values from current {name:
        value}."""
        elements = self.description.elements
        arrays = {}
        for name, (reference, _, _, offset) in elements.items():
            arrays.setdefault(reference, [None] * self.description.sizes[reference])
            arrays[reference][offset] = current.get(name)
        touched = sorted({elements[name][0] for name in values})
        for name, value in values.items():
            arrays[elements[name][0]][elements[name][3]] = value
        data = [x for reference in touched for x in arrays[reference]]
        if data:
            self.transfer(self.set_name, touched, (ctypes.c_double * len(data))(*data))

    def get_real(self, refs):
        """The values of the whole arrays refs, one list each."""
        sizes = [self.description.sizes[r] for r in refs]
        data = (ctypes.c_double * sum(sizes))()
        self.transfer(self.get_name, refs, data)
        values, first = [], 0
        for size in sizes:
            values.append(list(data[first:first + size]))
            first += size
        return values

    def free(self):
        self.call("Terminate")
        getattr(self.lib, self.fmi + "FreeInstance")(self.component)
        _ctypes.dlclose(self.lib._handle)
        self.lib = None


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


def compare_versions(results):
    """(summary, failures) of the 2.0 and 3.0 FMUs of each modelIdentifier
    of results: the same outputs, bitwise. 2.0's X.x[i], X.y[i], X.z[i]
    (a line's shape) are the 3.0 array X's row i."""
    summary, failures = [], []
    for identifier in sorted(set(results) & {k[len("fmi3/"):] for k in results
                                             if k.startswith("fmi3/")}):
        two, three = results[identifier], results["fmi3/" + identifier]
        names = {}
        for name in two:
            base, _, index = name.partition("[")
            column = "xyz".find(base[-1:]) + 1 if base[-2:-1] == "." else 0
            if name not in three and column and index:
                names[name] = f"{base[:-2]}[{index[:-1]},{column}]"
            else:
                names[name] = name
        if sorted(names.values()) != sorted(three):
            failures.append(f"{identifier}: the 3.0 FMU's outputs are not the 2.0 FMU's: "
                            f"{', '.join(sorted(set(three) ^ set(names.values()))[:6])}")
            continue
        differ = [name for name in two if two[name] != three[names[name]]]
        if differ:
            failures.append(f"{identifier}: {len(differ)} outputs of the 3.0 FMU differ from "
                            f"the 2.0 FMU's, {differ[0]} first")
        summary.append(f"{identifier}: {len(two) - len(differ)} of {len(two)} outputs of "
                       "the 3.0 FMU bit-identical to the 2.0 FMU's")
    return summary, failures


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

"""The C API of FMI 2.0 and 3.0 co-simulation FMUs through ctypes, for
stepFmus.py: an FMU's binary loaded and its instance called (Fmu), the
loggers, the statuses, and what the process runs on (glibc, the shared
objects loaded). Python 3.9 or later, x86-64 Linux.
"""
import ctypes
import os
import pathlib

import _ctypes

OK = 0  # fmi2OK, fmi3OK
FMI2_CO_SIMULATION = 1
STATUS = ("OK", "Warning", "Discard", "Error", "Fatal", "Pending")  # fmi2OK, fmi3OK, ...

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

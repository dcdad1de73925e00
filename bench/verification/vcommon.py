"""Shared helpers of the verification report: running rigidBodySim and
fmusim with their CPU time, error norms, observed orders, CSV files.

Every run is timed by the CPU time (user + system) of the child process,
from getrusage, so that other jobs on the machine do not enter it.
"""
import csv
import math
import os
import resource
import statistics
import subprocess

from foamfmi.bridgecase import fmu_path, vec  # noqa: F401
from foamfmi.implicitcase import ImplicitCase, slider, solver_entry  # noqa: F401

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
FMUSIM = os.path.join(TOP, "build", "bin", "fmusim")
DOCUMENTED = os.path.join(HERE, "documented.csv")


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


class Outcome:
    """The result of one run: 'ok' or 'failed' (with the error message),
    its tables and the child's CPU time."""

    def __init__(self, status, cpu, bodies=None, table=None, message=""):
        self.status, self.cpu, self.bodies, self.table = status, cpu, bodies, table
        self.message = message

    @property
    def ok(self):
        return self.status == "ok"


def first_error(log):
    """The words of a log that say why a run stopped: OpenFOAM's fatal
    error message, or its floating-point trap."""
    lines = [ln.strip() for ln in log.splitlines() if ln.strip()]
    for i, line in enumerate(lines):
        if "FOAM FATAL" in line:
            words = []
            for ln in lines[i + 1:]:
                if ln.startswith(("From ", "file:", "FOAM exiting")):
                    break
                words.append(ln)
            return " ".join(words).replace(TOP + "/", "")[:240]
    if any("sigFpe::sigHandler" in ln for ln in lines):
        return "floating-point exception trapped by OpenFOAM (SIGFPE)"
    return lines[-1][:240] if lines else "no output"


def fmi_message(stderr):
    """The FMU's own words from fmusim's last error line (after the fmi2
    status), else the line."""
    line = (stderr.strip().splitlines() or ["no message"])[-1]
    return line.split("(fmi2Error): ")[-1].replace(TOP + "/", "")[:200]


def has_nan(columns):
    return any(isinstance(x, float) and not math.isfinite(x)
               for values in columns.values() for x in values)


def run_rigid(name, model, end_time, delta_t, n_iter=1, connectors=()):
    """rigidBodySim on a model (rigidBodyMotionCoeffs text); an Outcome whose
    bodies are the bodies.dat columns and table the named connectors'."""
    case = ImplicitCase(name, model, end_time, delta_t)
    cpu0 = child_cpu()
    result = subprocess.run(["rigidBodySim", "-case", case.dir, "-nIter", str(n_iter)],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    cpu = child_cpu() - cpu0
    try:
        if result.returncode != 0:
            return Outcome("failed", cpu, message=first_error(result.stdout))
        bodies = case.bodies()
        table = {c: case.connector(c) for c in connectors}
        return Outcome("ok", cpu, bodies=bodies, table=table)
    finally:
        case.cleanup()


def run_fmusim(fmu, options, sets=None):
    """fmusim twobody; the Outcome's table is its CSV, as columns."""
    args = [FMUSIM, "twobody", fmu_path(fmu)]
    for key, value in options.items():
        args += [f"--{key}", " ".join(repr(float(x)) for x in value)
                 if isinstance(value, (tuple, list)) else str(value)]
    for key, value in (sets or {}).items():
        args += ["--set", f"{key}={value}"]
    cpu0 = child_cpu()
    result = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    cpu = child_cpu() - cpu0
    if result.returncode != 0:
        message = fmi_message(result.stderr)
        return Outcome("failed", cpu, message=f"fmusim exit {result.returncode}: {message}")
    rows = list(csv.reader(result.stdout.splitlines()))
    table = {name: [float(r[i]) for r in rows[1:]] for i, name in enumerate(rows[0])}
    return Outcome("ok", cpu, table=table)


def order(xs, ys):
    """Least-squares slope of log(y) against log(x)."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2:
        return float("nan")
    return statistics.linear_regression(*zip(*pts)).slope


def write_csv(path, header, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for row in rows:
            w.writerow([f"{x:.6g}" if isinstance(x, float) else x for x in row])


def read_documented():
    """documented.csv: quantity -> (value, low, high, reason)."""
    with open(DOCUMENTED) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    return {r[0]: (float(r[1]), float(r[2]), float(r[3]), r[4]) for r in rows[1:]}


def bisect_limit(is_stable, stable, unstable, rel=0.02):
    """The boundary between a stable and an unstable value of a parameter,
    by bisection in log space to a relative width rel: (last stable, first
    unstable)."""
    while unstable / stable > 1 + rel:
        mid = math.sqrt(stable * unstable)
        if is_stable(mid):
            stable = mid
        else:
            unstable = mid
    return stable, unstable

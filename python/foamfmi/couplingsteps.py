"""A floating body's coupling, time step by time step, read from a solver's
log: how many flow solves each step took and how far from the flow's own
answer each step left the body's acceleration.

Two kinds of coupling are read:

- an iterated one (this project's added-mass coupling, OpenFOAM's own
  with relaxation): PIMPLE's outer correctors, each printing
  "... outer corrector k, coupling residual r" (addedMassCoupling.C), the
  residual the change of the body's acceleration over the corrector;
- floatStepper's, which iterates nothing: per step a probe solve per free
  degree of freedom ("Virtual displacement for DoF"), a solve at zero
  acceleration and the step's own, each a PIMPLE loop, and the body's
  state after the step ("Body state after real time step:", its
  acceleration and angular acceleration, then its centre of mass). What
  its step leaves is measured after it: the acceleration the flow's force
  at the step's end (a forces function object on the body) implies,
  against the one the step took (equilibrium_residuals).

Both residuals are in the norm of addedMassCoupling::couplingResidual: the
change of the six accelerations, rotations weighted by the radius of
gyration sqrt(tr(I)/(3 m)), over the size of the true accelerations plus
0.01 |g|.
"""

import math
import os
import re

import numpy as np

from foamfmi import postprocessing

_TIME = re.compile(r"^Time = (\S+)", re.M)
_DELTA_T = re.compile(r"^deltaT = (\S+)", re.M)
_PIMPLE = re.compile(r"^PIMPLE: [Ii]teration", re.M)
_PROBE = re.compile(r"Virtual displacement for DoF")
_RESIDUAL = re.compile(r"outer corrector \d+, coupling residual ([^,\s]+)")
_VECTOR = r"\(([^)]*)\)"
_STATE = re.compile(r"Body state after real time step:.*?"
                    r"^Acceleration\s*: " + _VECTOR + r".*?"
                    r"^Angular acceleration\s*: " + _VECTOR + r".*?"
                    r"^Centre of mass\s*: " + _VECTOR, re.M | re.S)


class CouplingStepsError(ValueError):
    """A log or a forces file without what a step needs."""


def _vector(text):
    return [float(x) for x in text.split()]


def steps_from_log(text):
    """The time steps of a solver log, in order: dicts of time, deltaT
    (None where the log has none), flowSolves (PIMPLE loops, probe solves
    included), probeSolves, residuals (every corrector's coupling residual,
    in order) and, for floatStepper's, acceleration, angularAcceleration
    and centreOfMass after the step (else None)."""
    starts = list(_TIME.finditer(text))
    steps = []
    for k, start in enumerate(starts):
        end = starts[k + 1].start() if k + 1 < len(starts) else len(text)
        body = text[start.end():end]
        delta = _DELTA_T.search(text, starts[k - 1].end() if k else 0, start.start())
        probes = len(_PROBE.findall(body))
        state = _STATE.search(body)
        steps.append({
            "time": float(start.group(1)),
            "deltaT": float(delta.group(1)) if delta else None,
            "flowSolves": len(_PIMPLE.findall(body)) + probes,
            "probeSolves": probes,
            "residuals": [float(r) for r in _RESIDUAL.findall(body)],
            "acceleration": _vector(state.group(1)) if state else None,
            "angularAcceleration": _vector(state.group(2)) if state else None,
            "centreOfMass": _vector(state.group(3)) if state else None,
        })
    return steps


def read_forces(case, name):
    """{time: (total force, total moment about the function object's CofR)}
    of the forces function object `name` (postProcessing/<name>/<start
    time>/force.dat and moment.dat, v2012 and later: total, pressure and
    viscous columns, with or without brackets); the last start time's row
    wins where restarts overlap."""
    base = os.path.join(case, "postProcessing", name)
    if not os.path.isdir(base):
        raise CouplingStepsError("%s: no forces output (the function object %s)" % (base, name))
    starts = sorted(os.listdir(base), key=float)
    rows = {}
    for start in starts:
        tables = []
        for kind in ("force", "moment"):
            path = os.path.join(base, start, kind + ".dat")
            if not os.path.isfile(path):
                raise CouplingStepsError("%s: missing (the forces function object's %s)"
                                         % (path, kind))
            table = {}
            with open(path) as f:
                for line in f:
                    if line.startswith("#") or not line.strip():
                        continue
                    values = line.replace("(", " ").replace(")", " ").split()
                    if len(values) < 4:
                        continue
                    table[float(values[0])] = [float(x) for x in values[1:4]]
            tables.append(table)
        for t, force in tables[0].items():
            if t in tables[1]:
                rows[t] = (force, tables[1][t])
    if not rows:
        raise CouplingStepsError("%s: no rows" % base)
    return rows


def residual_norm(delta_linear, delta_angular, linear, angular, gyration, g):
    """addedMassCoupling::couplingResidual's norm: the change (delta_*) over
    the true accelerations' size plus 0.01 |g| [-]."""
    change = math.sqrt(sum((gyration * x) ** 2 for x in delta_angular)
                       + sum(x ** 2 for x in delta_linear))
    size = math.sqrt(sum((gyration * x) ** 2 for x in angular)
                     + sum(x ** 2 for x in linear))
    return change / (size + 0.01 * math.sqrt(sum(x ** 2 for x in g)))


def equilibrium_residuals(steps, forces, mass, inertia, g, cofr):
    """Per step with a body state and a forces row at its time: (time,
    residual), the residual between the accelerations the step took and
    those the flow's force and moment at its end imply, a = F/m + g and
    alpha = I^-1 M about the centre of mass (M = M_CofR - (c - CofR) x F;
    inertia: the principal moments about the centre of mass, the body's
    axes those of the global frame, as a body that pitches a few degrees),
    in residual_norm's norm."""
    gyration = math.sqrt(sum(inertia) / (3.0 * mass))
    times = np.array(sorted(forces))
    out = []
    for step in steps:
        if step["acceleration"] is None or not len(times):
            continue
        k = int(np.argmin(np.abs(times - step["time"])))
        if abs(times[k] - step["time"]) > 1e-9 * max(1.0, abs(step["time"])):
            continue
        force, moment = (np.array(v) for v in forces[times[k]])
        arm = np.array(step["centreOfMass"]) - np.array(cofr)
        moment_cm = moment - np.cross(arm, force)
        implied = force / mass + np.array(g)
        implied_angular = moment_cm / np.array(inertia)
        a = np.array(step["acceleration"])
        alpha = np.array(step["angularAcceleration"])
        out.append((step["time"], residual_norm(implied - a, implied_angular - alpha,
                                                a, alpha, gyration, g)))
    return out


def last_residuals(steps):
    """Per step with coupling residuals: (time, the last corrector's)."""
    return [(s["time"], s["residuals"][-1]) for s in steps if s["residuals"]]


def summary(steps, residuals):
    """{flowSolvesPerStep, residualMedian, residual95, residualMax,
    residualSteps} of the steps and their (time, residual) pairs."""
    if not steps:
        raise CouplingStepsError("no time steps")
    values = np.array([r for _, r in residuals]) if residuals else np.array([])
    out = {"flowSolvesPerStep": float(np.mean([s["flowSolves"] for s in steps])),
           "residualSteps": float(len(values))}
    if len(values):
        out.update(residualMedian=float(np.median(values)),
                   residual95=float(np.percentile(values, 95)),
                   residualMax=float(values.max()))
    return out


def write_steps(path, steps, residuals):
    """The steps as a table: Time, flow solves, the step's residual (nan
    where it has none)."""
    by_time = dict(residuals)
    with open(path, "w") as f:
        f.write("# Time flowSolves residual\n")
        for s in steps:
            f.write("%.9g %d %.6g\n" % (s["time"], s["flowSolves"],
                                       by_time.get(s["time"], float("nan"))))


def read_steps(path):
    """write_steps' table: (times, flow solves, residuals) as arrays."""
    rows = np.array(postprocessing.read_table(path))
    return rows[:, 0], rows[:, 1], rows[:, 2]

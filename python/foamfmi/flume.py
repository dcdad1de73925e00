"""The wave along a flume without a body (tutorials/mooredSectionWaves,
Allrun -empty-flume): the first-harmonic wave at gauges along it, the
incident wave separated from what the far end reflects, and how much of the
calibrated wave reaches each gauge.

A kept run is two files:
  run.dat     "key value" lines: the settings (period, height, the
              generator's distance, the resolution: cells per wave height in
              the free-surface band, cells per wavelength at the flume's far
              end, time steps per period, the time scheme), the cost (cells,
              timeSteps, executionTime) and the window measured over
  gauges.dat  a row per gauge: x (m, the section's position 0), the
              first-harmonic amplitude of the elevation, the incident and
              reflected amplitudes there (separated with the neighbouring
              gauges), the second harmonic's amplitude and the mean (m)
"""

import math
import os

import numpy as np

from foamfmi import harmonics, postprocessing, waves

STILL_WATER_DEPTH = 1.0  # m
MAX_WINDOW_PERIODS = 6
GAUGE_COLUMNS = ("x", "amplitude", "incident", "reflected", "second", "mean")


class FlumeError(ValueError):
    """A run that cannot be read or analysed."""


def separate_along(x, z, k, neighbours=2, decay=0.0):
    """Incident and reflected complex amplitudes at each gauge x[i] (sorted)
    from the complex first-harmonic amplitudes z: the reflected wave from
    a least-squares fit (harmonics.separate_waves, the incident wave
    decaying by `decay` per metre) over the gauge and its `neighbours`
    nearest gauges each side (at the ends, as many inward), the incident
    wave the gauge's own amplitude less the reflected one (so that the
    incident wave's loss along the flume is the gauges' own). Returns two
    lists of complex amplitudes at the gauges."""
    n = len(x)
    width = 2 * neighbours + 1
    if n < 2:
        raise FlumeError("%d gauges: at least two to separate the waves" % n)
    incident, reflected = [], []
    for i in range(n):
        lo = min(max(0, i - neighbours), max(0, n - width))
        sel = list(range(lo, min(n, lo + width)))
        zr = harmonics.separate_waves([z[j] for j in sel], [x[j] - x[i] for j in sel], k,
                                      decay)[1]
        incident.append(z[i] - zr)
        reflected.append(zr)
    return incident, reflected


def log_slope(x, a):
    """d ln a / dx of a least-squares fit a = a0 exp(slope x)."""
    return np.polyfit(np.asarray(x, dtype=float), np.log(np.asarray(a, dtype=float)), 1)[0]


def decay_per_metre(x, a):
    """The relative loss of amplitude per metre of travel (towards larger x)
    of a least-squares fit a = a0 exp(-d x): 1 - exp(-d)."""
    if len(x) < 2:
        return float("nan")
    return 1.0 - math.exp(log_slope(x, a))


def window(period, x_in, ramp_time, experiment=None):
    """(t0, t1, periods): the experiment's window at the section (its start
    after the wavemaker's start, 7 m before the section, moved by the
    travel time at the linear group velocity over the difference), at most
    MAX_WINDOW_PERIODS; without one, the front's arrival at the section and
    the ramp, MAX_WINDOW_PERIODS periods."""
    cg = waves.group_velocity_of_period(period, STILL_WATER_DEPTH)
    if experiment:
        t0 = experiment["windowDelay"] + (-x_in - 7.0) / cg
        n = min(int(round(experiment["windowPeriods"])), MAX_WINDOW_PERIODS)
    else:
        t0 = -x_in / cg + ramp_time
        n = MAX_WINDOW_PERIODS
    return t0, t0 + n * period, n


def analyse(period, times, eta, t0, t1):
    """The gauges' rows (GAUGE_COLUMNS) over [t0, t1]: eta {x: elevation
    series at times}."""
    omega = 2 * math.pi / period
    k = waves.wave_number(omega, STILL_WATER_DEPTH)
    xs = sorted(eta)
    fits = [harmonics.fit_window(times, eta[x], omega, t0, t1) for x in xs]
    z = [f.amplitudes[0] for f in fits]
    # The incident wave's decay: that of the gauges' amplitudes
    decay = -log_slope(xs, [abs(v) for v in z]) if len(xs) > 1 else 0.0
    incident, reflected = separate_along(xs, z, k, decay=decay)
    return [{"x": x, "amplitude": abs(f.amplitudes[0]), "incident": abs(zi),
             "reflected": abs(zr), "second": abs(f.amplitudes[1]), "mean": f.mean}
            for x, f, zi, zr in zip(xs, fits, incident, reflected)]


def summary(rows, calibrated, x_wp4=-1.5):
    """The wave (the first-harmonic amplitude of the elevation) at the
    first gauge, at WP_4 and at the last gauge (the section's position)
    per the calibrated amplitude, the loss per metre between the first and
    the last gauge, and the largest of the local estimates of the reflected
    wave per the wave there (the gauges' amplitudes differ from the
    incident wave's by at most that)."""
    first, last = rows[0], rows[-1]
    wp4 = min(rows, key=lambda r: abs(r["x"] - x_wp4))
    if abs(wp4["x"] - x_wp4) > 1e-6:
        raise FlumeError("no gauge at WP_4 (x = %g)" % x_wp4)
    return {"xFirst": first["x"], "xLast": last["x"],
            "first": first["amplitude"] / calibrated,
            "WP4": wp4["amplitude"] / calibrated,
            "last": last["amplitude"] / calibrated,
            "lossPerMetre": decay_per_metre([r["x"] for r in rows],
                                            [r["amplitude"] for r in rows]),
            "reflection": max(r["reflected"] / r["amplitude"] for r in rows)}


def write_kept(folder, run, rows):
    """folder/run.dat and folder/gauges.dat (module docstring)."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "run.dat"), "w") as f:
        f.write("# the flume alone (python/foamfmi/flume.py): key value\n")
        for key in sorted(run):
            value = run[key]
            f.write("%s %s\n" % (key, "%.9g" % value if isinstance(value, float) else value))
    with open(os.path.join(folder, "gauges.dat"), "w") as f:
        f.write("# first harmonic over the window (run.dat) at each gauge (m)\n")
        f.write("# " + " ".join(GAUGE_COLUMNS) + "\n")
        for r in rows:
            f.write(" ".join("%.7g" % r[c] for c in GAUGE_COLUMNS) + "\n")


def read_kept(folder):
    """(run, rows) of a folder written by write_kept."""
    run = postprocessing.read_key_values(os.path.join(folder, "run.dat"))
    path = os.path.join(folder, "gauges.dat")
    names, rows = None, []
    with open(path) as f:
        for line in f:
            words = line.lstrip("#").split()
            if line.startswith("#"):
                if words and words[0] == GAUGE_COLUMNS[0]:
                    names = words
            elif words and names:
                rows.append(dict(zip(names, (float(w) for w in words))))
    if names is None or any(c not in names for c in GAUGE_COLUMNS):
        raise FlumeError("%s: no header '# %s'" % (path, " ".join(GAUGE_COLUMNS)))
    return run, sorted(rows, key=lambda r: r["x"])

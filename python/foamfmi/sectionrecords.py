"""The raw records of the spring-moored ship section's flume experiment
(Sundsdal, Greco, Hanssen and Lugni; tutorials/mooredSectionWaves/
experimentRao, whose help text describes the data, the steady-state window
and the fits): the files of a data directory, a run's columns, its
wavemaker's start and period, its window, and the mean and first harmonic
of each quantity over it. Errors are RecordError, naming the file and what
was expected."""

import lzma
import math
import os
import re

import numpy as np

from foamfmi import harmonics


class RecordError(ValueError):
    """A data directory or record that cannot be read or analysed as the
    experiment's."""


# The docs' wave table (docs/experimental_setup.md): index -> T [s],
# k [rad/m], c_g [m/s], reflection time [s]
WAVES = {
    1: (1.516, 1.750, 1.184, 10.137), 2: (1.269, 2.500, 0.990, 12.116),
    3: (1.238, 2.625, 0.967, 12.415), 4: (1.210, 2.750, 0.944, 12.707),
    5: (1.183, 2.875, 0.924, 12.993), 6: (1.158, 3.000, 0.904, 13.272),
    7: (1.113, 3.250, 0.869, 13.814), 8: (1.072, 3.500, 0.837, 14.335),
    9: (1.036, 3.750, 0.809, 14.839), 10: (0.897, 5.000, 0.700, 17.134),
    11: (0.802, 6.250, 0.626, 19.157), 12: (0.733, 7.500, 0.572, 20.985),
    13: (0.678, 8.750, 0.529, 22.666), 14: (0.634, 10.000, 0.495, 24.231),
}
HEIGHTS = {1: 0.024, 2: 0.04}         # wave height per height index [m]
MODEL_X = 7.0                          # section from the wavemaker [m]
RAMP_PERIODS = 5                       # linear ramp up (and down) [periods]
START_FRACTION = 0.005                 # of the stroke: wavemaker moving
FREQUENCY_TOLERANCE = 0.01             # WM_Position against the table's T
UPSTREAM_GAUGE = "WP_4"                # 5.5 m: 1.5 m before the section
SERIES_SAMPLES_PER_PERIOD = 32

# Quantities of a scenario B run: (name in measured.dat, CSV column, scale)
QUANTITIES = [
    ("sway", "Sway", 1.0),                   # m
    ("heave", "Heave", 1.0),                 # m
    ("roll", "Roll", 180.0 / math.pi),       # deg
    ("tensionSB", "Tension_SB", 1.0),        # N
    ("tensionPS", "Tension_PS", 1.0),        # N
    ("forceSway", "Force_Sway", 1.0),        # N
    ("wpUp", UPSTREAM_GAUGE, 1.0),           # m
]


def read_source(data_dir):
    """Repository URL and commit named in DIR/SOURCE."""
    path = os.path.join(data_dir, "SOURCE")
    try:
        with open(path) as f:
            text = f.read()
    except OSError as e:
        raise RecordError("cannot read %s (the data's origin): %s" % (path, e.strerror))
    url = re.search(r"Repository:\s*(\S+)", text)
    commit = re.search(r"Commit:\s*([0-9a-f]{40})", text)
    if not url or not commit:
        raise RecordError("%s: expected the lines 'Repository: URL' and 'Commit: <40 hex digits>'" % path)
    return url.group(1), commit.group(1)


def run_files(directory, pattern):
    """{run name: file} of the files run.csv or run.csv.xz in directory
    whose run name matches pattern."""
    runs = {}
    for f in os.listdir(directory):
        m = re.fullmatch(r"(.+)\.csv(\.xz)?", f)
        if m and re.fullmatch(pattern, m.group(1)):
            if m.group(1) in runs:
                raise RecordError("%s: both %s and %s" % (directory, runs[m.group(1)], f))
            runs[m.group(1)] = f
    return runs


def read_csv(path, required):
    """Columns of a CSV file (xz-compressed if its name ends in .xz) by
    their name without the unit ("WP_4 [m]" -> "WP_4"); a leading unnamed
    index column is dropped."""
    opener = lzma.open if path.endswith(".xz") else open
    try:
        with opener(path, "rt") as f:
            names = [h.split("[")[0].strip() for h in f.readline().strip().split(",")]
            data = np.loadtxt(f, delimiter=",", ndmin=2)
    except (OSError, lzma.LZMAError, UnicodeDecodeError) as e:
        raise RecordError("cannot read %s: %s" % (path, e))
    except ValueError as e:
        raise RecordError("%s: expected rows of %d numbers after the header: %s" % (path, len(names), e))
    if data.shape[1] != len(names):
        raise RecordError("%s: %d columns in the rows, %d in the header" % (path, data.shape[1], len(names)))
    if names[0] == "":
        names, data = names[1:], data[:, 1:]
    columns = {n: data[:, i] for i, n in enumerate(names)}
    missing = [n for n in ["Time"] + required if n not in columns]
    if missing:
        raise RecordError("%s: no column %s (columns: %s)" % (path, ", ".join(missing), ", ".join(names)))
    t = columns["Time"]
    if len(t) < 400 or np.any(np.diff(t) <= 0):
        raise RecordError("%s: expected at least 2 s of increasing times at 200 Hz" % path)
    return columns


def wavemaker_times(path, t, wm):
    """Start and stop of the wavemaker: first and last samples departing from
    rest (median of the first second) by more than START_FRACTION of the
    stroke amplitude."""
    rest = np.median(wm[t < t[0] + 1.0])
    departure = np.abs(wm - rest)
    moving = np.nonzero(departure > START_FRACTION * departure.max())[0]
    if len(moving) < 2 or moving[0] == 0:
        raise RecordError("%s: WM_Position does not start from rest" % path)
    return t[moving[0]], t[moving[-1]]


def dominant_frequency(t, y):
    """Frequency [Hz] of the largest periodogram peak of y (mean removed):
    the FFT's peak (zero-padded to 1/16 of the record's resolution), refined
    to 1e-5 Hz by the discrete Fourier sum around it."""
    y = y - y.mean()
    dt = (t[-1] - t[0]) / (len(t) - 1)
    n = 16 * 2 ** int(math.ceil(math.log2(len(y))))
    spectrum = np.abs(np.fft.rfft(y, n))
    f = (np.argmax(spectrum[1:]) + 1) / (n * dt)
    fine = np.arange(f - 2 / (n * dt), f + 2 / (n * dt), 1e-5)
    power = [abs(np.dot(y, np.exp(-2j * math.pi * g * t))) for g in fine]
    return fine[int(np.argmax(power))]


def steady_window(path, t, wm, period_index):
    """Window [start, end] of whole periods (experimentRao's help text),
    its start after t0 and its number of periods; checks T against
    WM_Position."""
    T, _, cg, t_refl = WAVES[period_index]
    t0, t_stop = wavemaker_times(path, t, wm)
    active = (t >= t0) & (t <= t_stop)
    f = dominant_frequency(t[active], wm[active])
    if abs(f * T - 1) > FREQUENCY_TOLERANCE:
        raise RecordError("%s: WM_Position oscillates at %.4f Hz (T = %.4f s), the docs' table "
                          "gives T = %.3f s for period index %d: more than %g %% apart"
                          % (path, f, 1 / f, T, period_index, 100 * FREQUENCY_TOLERANCE))
    start = t0 + RAMP_PERIODS * T + MODEL_X / cg
    end = min(t0 + MODEL_X / cg + t_refl, t_stop - RAMP_PERIODS * T + MODEL_X / cg)
    periods = int(math.floor((end - start) / T + 1e-9))
    if periods < 1:
        raise RecordError("%s: no whole period between the steady waves' arrival (%.2f s) "
                          "and the reflection or ramp-down (%.2f s)" % (path, start, end))
    if start + periods * T > t[-1]:
        raise RecordError("%s: the record ends at %.2f s, before the window's end %.2f s"
                          % (path, t[-1], start + periods * T))
    return {"t0": t0, "start": start, "end": start + periods * T,
            "delay": start - t0, "periods": periods, "fWM": f}


def window_fit(t, y, omega, w, shift=0.0):
    """Mean and first-harmonic amplitude over the window (moved by shift);
    None when y is constant there (not recorded in that run)."""
    inside = (t >= w["start"] + shift) & (t < w["end"] + shift)
    if np.ptp(y[inside]) == 0:
        return None
    f = harmonics.fit(t[inside], y[inside], omega)
    return f.mean, abs(f.amplitudes[0])


def analyse_model_run(path, pp):
    """A scenario B run of period index pp: its window, the mean and
    first-harmonic amplitude of each of QUANTITIES over it (None where
    not recorded, named in "missing"), the amplitudes over the window
    moved by a period either way ("shifted", None beyond the record) and
    its series for the overlays."""
    need = ["WM_Position"] + [c for _, c, _ in QUANTITIES]
    col = read_csv(path, need)
    t = col["Time"]
    w = steady_window(path, t, col["WM_Position"], pp)
    omega = 2 * math.pi / WAVES[pp][0]
    T = WAVES[pp][0]
    r = {"window": w, "missing": []}
    for name, c, scale in QUANTITIES:
        fit = window_fit(t, scale * col[c], omega, w)
        if fit is None:
            r["missing"].append(c)
            r[name + "Mean"] = r[name + "Amp"] = None
        else:
            r[name + "Mean"], r[name + "Amp"] = fit
    # The window moved by a period either way, where the record has it
    r["shifted"] = {}
    for shift in (-1, 1):
        r["shifted"][shift] = None
        if w["start"] + shift * T >= t[0] and w["end"] + shift * T <= t[-1]:
            amps = {}
            for name, c, scale in QUANTITIES:
                fit = window_fit(t, scale * col[c], omega, w, shift * T)
                amps[name + "Amp"] = None if fit is None else fit[1]
            r["shifted"][shift] = amps
    r["series"] = measured_series(col, w, T)
    return r


def measured_series(col, w, T):
    """The run's series for the overlays (docstring): rows of Time after
    t0, Sway, Heave (from rest), Roll (deg), Tension_SB, Tension_PS, WP_4."""
    t = col["Time"]
    rest = t < t[0] + 1.0
    grid = np.arange(max(t[0], w["start"] - RAMP_PERIODS * T),
                     min(t[-1], w["end"] + T), T / SERIES_SAMPLES_PER_PERIOD)
    columns = [grid - w["t0"]]
    for c, scale, tare in (("Sway", 1.0, True), ("Heave", 1.0, True),
                           ("Roll", 180.0 / math.pi, False), ("Tension_SB", 1.0, False),
                           ("Tension_PS", 1.0, False), (UPSTREAM_GAUGE, 1.0, False)):
        y = scale * col[c]
        if tare:
            y = y - np.median(y[rest])
        columns.append(np.interp(grid, t, y))
    return np.column_stack(columns)


def analyse_calibration_run(path, pp):
    """A calibrated-wave run (no section) of period index pp: its window and
    the wave's first-harmonic amplitude a at UPSTREAM_GAUGE over it."""
    col = read_csv(path, ["WM_Position", UPSTREAM_GAUGE])
    t = col["Time"]
    w = steady_window(path, t, col["WM_Position"], pp)
    fit = window_fit(t, col[UPSTREAM_GAUGE], 2 * math.pi / WAVES[pp][0], w)
    if fit is None:
        raise RecordError("%s: %s is constant over the window" % (path, UPSTREAM_GAUGE))
    return {"window": w, "a": fit[1]}

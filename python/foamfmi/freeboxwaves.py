"""The free-floating box of Ren et al. (2015) in regular waves
(tutorials/freeBoxWaves) against the measured curves: a run's response as a
resampled series (what the repository keeps of a run), the measured curves
(FloatStepper's digitisation), and their comparison.

A run is two files (write_run, read_run):
  run.dat     "key value" lines: the settings that produced it (height,
              meshFactor, endTime, coupling, pitchInertia,
              centreOfMassHeight, morphing, nProcs; runs kept before the
              last three were settings had FloatStepper's box and the short
              morphing, RUN_DEFAULTS), the cost
              (cells, timeSteps, executionTime) and where it came from
              (commit, openfoam)
  series.dat  columns Time, surge, heave (m, the centre of mass from its
              start at x = 2 m on the still-water level), pitch (deg, about
              y: the lee side down) and the elevation (m) at the gauges
              x = 1 m and 3 m, every T/32 (linear interpolation of the
              solver's steps)

The measured curves (experiment/Ren2015data/H0<cm><quantity>, two columns)
are normalised as FloatStepper's compareExpNum.py reads them: time t/T,
surge x/d and heave z/d (d = 0.4 m, the water depth), pitch theta/(k d)
(k = 2 pi/1.93625 m), the elevation eta/d; read_experiment turns them into
s, m and degrees.

The comparison (compare) is made over whole periods of the steady waves:
in the run, from the waves' arrival at the box (the front's travel at the
linear group velocity from the generator, plus the ramp); in the
experiment, whose curves start at an unstated time once the waves have
reached the box, from their start. Each record is fitted by a mean, a
linear drift and the first two harmonics (least squares); amplitudes are
the first harmonic's. The experiment's clock is set to the run's by the
heave's first-harmonic phase, so phases are compared relative to the
heave: surge and pitch against heave, in both. The experiment's gauge
position is not stated (FloatStepper plots it against its gauge at
x = 1 m, as here): its amplitude is compared, not its phase.
"""

import cmath
import math
import os

import numpy as np

from foamfmi import harmonics, plots, postprocessing, uncertainty, waves

PERIOD = 1.2  # s, both wave heights
DEPTH = 0.4  # m, still water; the experiment's normalising length d
BOX_X = 2.0  # m, the box's centre from the generator (constant/dynamicMeshDict)
RAMP_TIME = 4.0  # s, constant/waveProperties
# kg m^2, the box's about its centre of mass in FloatStepper's case (Allrun's
# default); runs kept before it was a setting had it
PITCH_INERTIA = 0.15106368
# FloatStepper's wavelength for the pitch's normalisation k d
EXPERIMENT_WAVELENGTH = 1.93625
GAUGES = (1.0, 3.0)  # m, system/waveGauges (Allrun)
COMPARED_GAUGE = 1.0
WINDOW_PERIODS = 3
SAMPLES_PER_PERIOD = 32
HEIGHTS = {0.04: "H004", 0.10: "H010"}
# Quantity: (file suffix, unit, the measured value per the file's)
QUANTITIES = {
    "surge": ("Surge", "m", DEPTH),
    "heave": ("Heave", "m", DEPTH),
    "pitch": ("Pitch", "deg", math.degrees(2 * math.pi / EXPERIMENT_WAVELENGTH * DEPTH)),
    "wave": ("WaveGauge", "m", DEPTH),
}
SERIES_COLUMNS = ("Time", "surge", "heave", "pitch") + tuple("eta.%g" % x for x in GAUGES)
RUN_KEYS = ("height", "meshFactor", "endTime", "coupling", "nProcs")
# Settings with a value for runs that did not log them
RUN_DEFAULTS = {"pitchInertia": PITCH_INERTIA, "centreOfMassHeight": 0.0, "morphing": "short"}
# The header lines of run.dat and series.dat
RUN_TITLE = "freeBoxWaves run (python/foamfmi/freeboxwaves.py): key value"
SERIES_TITLE = ("freeBoxWaves response every T/%d: surge, heave (m), pitch (deg), "
                "elevation at the gauges (m)" % SAMPLES_PER_PERIOD)


class FreeBoxError(ValueError):
    """A run or a measured curve that cannot be read or compared."""


def experiment_name(height):
    """H004 or H010: the measured curves' stem for a wave height (m)."""
    for h, name in HEIGHTS.items():
        if abs(height - h) < 1e-6:
            return name
    raise FreeBoxError("no measured curves for a wave height of %g m (measured: %s m)"
                       % (height, ", ".join("%g" % h for h in HEIGHTS)))


def window_start():
    """Time (s) after the generator's start at which the full waves have
    reached the box: the front's travel at the linear group velocity and
    the ramp."""
    return BOX_X / waves.group_velocity_of_period(PERIOD, DEPTH) + RAMP_TIME


def default_end_time(periods=WINDOW_PERIODS):
    """The run's default end: the window of the given periods and one
    more (compare may start the window up to half a period later, on the
    measured curves' start), to the ms."""
    return round(window_start() + (periods + 1) * PERIOD, 3)


# ------------------------------------------------------- the experiment --

def read_experiment(folder, height):
    """{quantity: (t in s, value in m or deg)} of the measured curves of
    this wave height in folder (experiment/Ren2015data)."""
    stem = experiment_name(height)
    curves = {}
    for q, (suffix, _, scale) in QUANTITIES.items():
        path = os.path.join(folder, stem + suffix)
        rows = np.array(postprocessing.read_table(path))
        if rows.ndim != 2 or rows.shape[1] != 2 or len(rows) < 20:
            raise FreeBoxError("%s: expected two columns (t/T, value) of 20 rows or more" % path)
        curves[q] = (rows[:, 0] * PERIOD, rows[:, 1] * scale)
    return curves


# ---------------------------------------------------------------- a run --

def _set_defaults(run, source):
    """run[key] for each setting of RUN_DEFAULTS: source's, else the
    default, of the default's type (a number, or the morphing's name)."""
    for key, value in RUN_DEFAULTS.items():
        run[key] = type(value)(source.get(key, value))


def read_case(case):
    """A finished (or stopped) run of the tutorial: (run, series)."""
    logged = postprocessing.run_settings(case)
    run = {}
    for key in RUN_KEYS:
        if key not in logged:
            raise FreeBoxError("%s/log.runSettings: no %s" % (case, key))
        run[key] = logged[key] if key == "coupling" else float(logged[key])
    _set_defaults(run, logged)
    run["cells"] = postprocessing.mesh_cells(os.path.join(case, "log.checkMesh"))
    app = postprocessing.case_solver(case)
    log = postprocessing.solver_log(os.path.join(case, "log." + app))
    run.update(timeSteps=log["timeSteps"], executionTime=log["executionTime"],
               commit=postprocessing.project_commit(), openfoam=os.environ.get("WM_PROJECT_VERSION", "unknown"))
    motion = np.array(postprocessing.read_table(
        os.path.join(case, "postProcessing", "rigidBodyMotion", "box.dat")))
    t = motion[:, 0]
    grid = np.arange(0.0, t[-1] + 1e-9, PERIOD / SAMPLES_PER_PERIOD)
    # From t = 0 at rest: the state of the first step until then
    series = {"Time": grid, "surge": np.interp(grid, t, motion[:, 1] - BOX_X),
              "heave": np.interp(grid, t, motion[:, 3] - DEPTH),
              "pitch": np.interp(grid, t, motion[:, 6])}
    times, eta = postprocessing.read_gauges(case, DEPTH)
    for x in GAUGES:
        nearest = min(eta, key=lambda g: abs(g - x))
        if abs(nearest - x) > 0.02:
            raise FreeBoxError("no wave gauge near x = %g m; the gauges are at %s"
                               % (x, ", ".join("%g" % g for g in sorted(eta))))
        series["eta.%g" % x] = np.interp(grid, times, eta[nearest])
    return run, series


def write_run(folder, run, series):
    """folder/run.dat and folder/series.dat (module docstring)."""
    postprocessing.write_kept_run(folder, run, series, SERIES_COLUMNS, RUN_TITLE, SERIES_TITLE)


def read_run(folder):
    """(run, series) of a folder written by write_run."""
    run, series = postprocessing.read_kept_run(folder, SERIES_COLUMNS, RUN_KEYS)
    _set_defaults(run, run)
    return run, series


# ------------------------------------------------------------ analysis --

def fit(t, y, t0, t1):
    """Least-squares fit over [t0, t1] of a mean, a linear drift and the
    first two harmonics of the wave frequency: (mean at the window's
    middle, drift velocity per s, complex first-harmonic amplitude Z with
    y ~ Re(Z exp(i omega t)))."""
    omega = 2 * math.pi / PERIOD
    tw, yw = harmonics.in_window(t, y, t0, t1)
    a = np.column_stack([harmonics.design_matrix(tw, omega, 2), tw - 0.5 * (t0 + t1)])
    c = np.linalg.lstsq(a, yw, rcond=None)[0]
    return float(c[0]), float(c[5]), complex(c[1], -c[2])


def _phase(z, reference):
    """Phase of z relative to reference, degrees in (-180, 180]."""
    return math.degrees(cmath.phase(z / reference))


def compare(series, curves, periods=WINDOW_PERIODS):
    """The run's series against the measured curves over the window:
    {key: value} (amplitudes, RAOs per each's gauge amplitude, phases
    relative to heave, drift velocities, the clock shift), or None when
    the run has no whole period after the waves' arrival."""
    t0 = window_start()
    t_end = series["Time"][-1] + 1e-9
    if t_end < t0 + PERIOD:
        return None
    # The curves from the latest of their first samples (within 0.2 s of 0)
    start = max(t[0] for t, _ in curves.values())
    columns = {"surge": "surge", "heave": "heave", "pitch": "pitch",
               "wave": "eta.%g" % COMPARED_GAUGE}
    # The experiment's clock: t = t_experiment + s puts its heave in phase
    # with the run's over the first period, Z_e exp(-i omega s) parallel to
    # Z_cfd; of those s the one that lays its start nearest the run's window
    z_cfd = fit(series["Time"], series["heave"], t0, t0 + PERIOD)[2]
    z_exp = fit(*curves["heave"], start, start + PERIOD)[2]
    lag = cmath.phase(z_exp / z_cfd) * PERIOD / (2 * math.pi)
    shift = lag + PERIOD * round((t0 - start - lag) / PERIOD)
    # The same window in both: from the waves' arrival at the box, or the
    # curves' start on the run's clock if later, over whole periods that
    # both cover
    t0 = max(t0, start + shift)
    n = min(periods, int((t_end - t0) / PERIOD),
            int((min(t[-1] for t, _ in curves.values()) + shift - t0) / PERIOD + 1e-9))
    if n < 1:
        return None
    t1 = t0 + n * PERIOD
    r = {"windowStart": t0, "windowEnd": t1, "windowPeriods": n, "clockShift": shift}
    cfd = {q: fit(series["Time"], series[c], t0, t1) for q, c in columns.items()}
    exp = {q: fit(t, y, t0 - shift, t1 - shift) for q, (t, y) in curves.items()}
    k = 2 * math.pi / EXPERIMENT_WAVELENGTH
    for name, fits in (("cfd", cfd), ("experiment", exp)):
        a = abs(fits["wave"][2])
        for q in QUANTITIES:
            r["%s.%s.amplitude" % (name, q)] = abs(fits[q][2])
            r["%s.%s.drift" % (name, q)] = fits[q][1]
            r["%s.%s.mean" % (name, q)] = fits[q][0]
        r["%s.surge.rao" % name] = abs(fits["surge"][2]) / a
        r["%s.heave.rao" % name] = abs(fits["heave"][2]) / a
        r["%s.pitch.rao" % name] = math.radians(abs(fits["pitch"][2])) / (k * a)
        for q in ("surge", "pitch"):
            r["%s.%s.phase" % (name, q)] = _phase(fits[q][2], fits["heave"][2])
    for q in QUANTITIES:
        e, c = r["experiment.%s.amplitude" % q], r["cfd.%s.amplitude" % q]
        r["%s.amplitudeError" % q] = (c - e) / e
    for q in ("surge", "heave", "pitch"):
        e, c = r["experiment.%s.rao" % q], r["cfd.%s.rao" % q]
        r["%s.raoError" % q] = (c - e) / e
    for q in ("surge", "pitch"):
        d = r["cfd.%s.phase" % q] - r["experiment.%s.phase" % q]
        r["%s.phaseError" % q] = (d + 180.0) % 360.0 - 180.0
    return r


def table_lines(r):
    """The comparison as a Markdown table."""
    lines = ["| quantity | experiment | CFD | error |", "| --- | --- | --- | --- |"]
    for q, (_, unit, _) in QUANTITIES.items():
        lines.append("| %s amplitude (%s) | %.4g | %.4g | %+.1f %% |"
                     % (q, unit, r["experiment.%s.amplitude" % q], r["cfd.%s.amplitude" % q],
                        100 * r["%s.amplitudeError" % q]))
    for q, unit in (("surge", "m/m"), ("heave", "m/m"), ("pitch", "rad/(k a)")):
        lines.append("| %s RAO (%s) | %.4g | %.4g | %+.1f %% |"
                     % (q, unit, r["experiment.%s.rao" % q], r["cfd.%s.rao" % q],
                        100 * r["%s.raoError" % q]))
    for q in ("surge", "pitch"):
        lines.append("| %s phase against heave (deg) | %.1f | %.1f | %+.1f deg |"
                     % (q, r["experiment.%s.phase" % q], r["cfd.%s.phase" % q],
                        r["%s.phaseError" % q]))
    lines.append("| surge drift velocity (mm/s) | %.3g | %.3g | |"
                 % (1e3 * r["experiment.surge.drift"], 1e3 * r["cfd.surge.drift"]))
    return lines


def write_comparison(path, r):
    with open(path, "w") as f:
        f.write("".join("%s %.6g\n" % (k, v) for k, v in sorted(r.items())))


# ---------------------------------------------------------------- plots --

def plot_overlay(plot_dir, name, run, r, experiment_dir):
    """plot_dir/name.png: the run (plot_dir/series.dat) and the measured
    curves on the run's clock (shifted by the heave's phase), the window
    shaded: the elevation at x = 1 m, surge, heave, pitch. The measured
    surge, from the box's position when the curves start, is offset to the
    run's mean over the window."""
    stem = os.path.join(experiment_dir, experiment_name(run["height"]))
    own = os.path.join(plot_dir, "series.dat")
    col = {c: i + 1 for i, c in enumerate(SERIES_COLUMNS)}
    s = r["clockShift"]
    panels = (("wave", "elevation at x = 1 m (m)", col["eta.%g" % COMPARED_GAUGE]),
              ("surge", "surge (m)", col["surge"]), ("heave", "heave (m)", col["heave"]),
              ("pitch", "pitch (deg)", col["pitch"]))
    lines = ["set terminal " + plots.terminal("1000,1100"),
             "set output '%s/%s.png'" % (plot_dir, name), "set termoption noenhanced",
             "set multiplot layout 4,1 title \"Free box, H = %g m, T = %g s: CFD (mesh factor "
             "%g, %s coupling) and Ren et al. (2015), the window grey\""
             % (run["height"], PERIOD, run["meshFactor"], run["coupling"]),
             "set grid", "set key top left opaque", "set lmargin 10",
             "set xrange [%g:%g]" % (max(0.0, s - PERIOD), s + 6 * PERIOD),
             plots.shade(r["windowStart"], r["windowEnd"])]
    for q, label, c in panels:
        offset = r["cfd.surge.mean"] - r["experiment.surge.mean"] if q == "surge" else 0.0
        if q == "pitch":
            lines.append("set xlabel 't after the generator starts (s)'")
        lines += ['set ylabel "%s"' % label,
                  "plot '%s' u 1:%d w l lw 1.6 lc rgb '#1f5fbf' t 'CFD', "
                  "'%s%s' u ($1*%.9g+%.9g):($2*%.9g+%.9g) w lp pt 7 ps 0.5 lc rgb 'black' "
                  "t 'experiment%s'" % (own, c, stem, QUANTITIES[q][0], PERIOD, s,
                                        QUANTITIES[q][2], offset,
                                        " + %.3g m" % offset if offset else "")]
    lines.append("unset multiplot")
    plots.gnuplot(os.path.join(plot_dir, name + ".gp"), lines)


# --------------------------------------------------- the kept runs --

def mesh_study(rows):
    """Numerical uncertainty from the kept runs of one wave and coupling
    on three or more mesh factors (the three finest): {quantity: (U,
    how, values fine to coarse, mesh factors)} of the amplitudes, U in
    their units (foamfmi.uncertainty: GCI, else 3 x range)."""
    rows = sorted(rows, key=lambda rr: -rr[0]["meshFactor"])[:3]
    if len(rows) < 3:
        return {}
    factors = [rr[0]["meshFactor"] for rr in rows]
    out = {}
    for q in QUANTITIES:
        phi = [rr[1]["cfd.%s.amplitude" % q] for rr in rows]
        if max(phi) == min(phi):
            out[q] = (0.0, "the same on all three", phi, factors)
            continue
        u, _, how = uncertainty.numerical_uncertainty(phi, [1 / f for f in factors])
        out[q] = (u, how, phi, factors)
    return out

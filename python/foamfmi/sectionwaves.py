"""The spring-moored ship section in regular waves
(tutorials/mooredSectionWaves) against the NTNU flume experiment: a run's
response as a resampled series (what the repository keeps of a run), and
its analysis with the experiment's definitions.

A run is two files:
  run.dat     "key value" lines: the settings that produced it (period,
              height, meshFactor, rampPeriods, endTime, nProcs), the flume
              (xIn, the gauges' x), the cost (cells, timeSteps,
              executionTime) and where it came from (commit, openfoam)
  series.dat  columns Time, sway, heave (m, from the first time step),
              roll (deg, about y: the lee side down), tensionWeather,
              tensionLee (N, the springs' tensions), and the elevation (m)
              at each gauge (eta.<gauge>), resampled every T/32 (linear
              interpolation of the solver's steps)

The analysis (analyse) follows the experiment's (experiment/README.md):
over the same window relative to the waves' arrival at the section (the
generator is 7 m before it in both), first harmonics of a least-squares
fit of a mean, the first and the second harmonic; RAOs per the incident
wave's amplitude at the gauge WP_4 (here separated from the wave the
section reflects by three gauges, harmonics.separate_waves; the
experiment's, a calibrated run without the section), roll per k0 a with
the deep-water k0 = omega^2/g of the experiment's table; each spring on
its own, as the experiment's two ring gauges, and tared at rest (the
tension at the first time step), so that their means are the mean drift
load's share.
"""

import math
import os

import numpy as np

from foamfmi import dictionary, harmonics, plots, postprocessing, waves

STILL_WATER_DEPTH = 1.0  # m, system/setFieldsDict
SECTION_X = 0.0  # m, the section's centre (system/blockMeshDict)
DEFAULT_PERIODS = 6  # window of a wave the experiment did not measure
EXPERIMENT_GENERATOR = 7.0  # m, the experiment's wavemaker before the section
SAMPLES_PER_PERIOD = 32
# Allrun's flume switches as log.runSettings names them, logged only when
# given (-cells-per-height, -cells-per-wavelength, -steps-per-period,
# -ddt, -momentum-ddt, -momentum-scheme, -phase-advection,
# -inlet-absorption; a scheme's spaces as _): without them, the case's own
# flume
FLUME_KEYS = ("cellsPerHeight", "cellsPerWavelength", "stepsPerPeriod", "ddt",
              "momentumDdt", "momentumScheme", "phaseAdvection", "inletAbsorption")
SPRINGS = {"tensionWeather": "springWeather", "tensionLee": "springLee"}
# Gauges: their key in constant/runSettings by their name in series.dat
GAUGES = {"separation2": "gaugeSeparation2", "separation1": "gaugeSeparation1",
          "WP4": "gaugeWP4", "down": "gaugeDown"}
INCIDENT_GAUGES = ("separation2", "separation1", "WP4")
# The experiment's springs, 30 N/m each; 59.72 N/m together (offset tests)
EXPERIMENT_SPRING_STIFFNESS = 0.5 * 59.72
# Quantities compared, (key, label, unit of the RAO)
QUANTITIES = (("sway", "sway", "m/m"), ("heave", "heave", "m/m"),
              ("roll", "roll", "rad/rad"),
              ("tensionWeather", "weather spring (experiment: starboard)", "N/m"),
              ("tensionLee", "lee spring (experiment: port side)", "N/m"),
              ("tensionMean", "the springs' mean", "N/m"))


class SectionWavesError(ValueError):
    """A run or an experiment table that cannot be read or analysed."""


# ---------------------------------------------------------------- a run --

def ddt_label(run):
    """A run's time scheme in words (run.dat's ddt, the case's
    CrankNicolson 0.5 when not logged), the momentum's when Allrun
    -momentum-ddt gave it its own, and the phase fraction's isoAdvector
    (Allrun -phase-advection), which takes no time scheme."""
    ddt = str(run.get("ddt", "CrankNicolson_0.5")).replace("_", " ")
    if run.get("momentumDdt"):
        ddt += "; ddt(rho,U) " + str(run["momentumDdt"]).replace("_", " ")
    if run.get("phaseAdvection", "MULES") != "MULES":
        ddt += "; alpha by " + str(run["phaseAdvection"])
    return ddt


def read_case(case):
    """A finished (or stopped) run of the tutorial: (run, series) as
    write_run writes them."""
    settings_path = os.path.join(case, "constant", "runSettings")
    if not os.path.isfile(settings_path):
        raise SectionWavesError("no %s (written by Allrun)" % settings_path)
    logged = postprocessing.run_settings(case)
    run = {"period": dictionary.read_scalar(settings_path, "wavePeriod"),
           "height": dictionary.read_scalar(settings_path, "waveHeight"),
           "rampTime": dictionary.read_scalar(settings_path, "rampTime"),
           "xIn": dictionary.read_scalar(settings_path, "xIn")}
    for key in ("meshFactor", "endTime", "rampPeriods", "nProcs"):
        run[key] = float(logged[key]) if key in logged else float("nan")
    run["guideFriction"] = float(logged.get("guideFriction", 0))
    # The section's inputs (Allrun -mass, -kg, -spring-rate; a run logged
    # before they were options had constant/dynamicMeshDict's)
    for key in ("mass", "KG", "springRate"):
        if key in logged:
            run[key] = float(logged[key])
    # The generator's height over the wave's (Allrun -incident-scale),
    # logged only when not 1
    if "incidentScale" in logged:
        run["incidentScale"] = float(logged["incidentScale"])
    # OpenFOAM's own coupling (Allrun -coupling stock), logged only then
    if "coupling" in logged:
        run["coupling"] = logged["coupling"]
    for key in FLUME_KEYS:
        if key in logged:
            value = logged[key]
            try:
                run[key] = float(value)
            except ValueError:
                run[key] = value
    for name, key in GAUGES.items():
        run["gauge." + name] = dictionary.read_scalar(settings_path, key)
    run["cells"] = postprocessing.mesh_cells(os.path.join(case, "log.checkMesh"))
    app = postprocessing.case_solver(case)
    log = postprocessing.solver_log(os.path.join(case, "log." + app))
    run["timeSteps"] = log["timeSteps"]
    run["executionTime"] = log["executionTime"]
    run["commit"] = postprocessing.project_commit()
    run["openfoam"] = os.environ.get("WM_PROJECT_VERSION", "unknown")
    T = run["period"]
    run["sampleInterval"] = T / SAMPLES_PER_PERIOD

    motion = np.array(postprocessing.read_table(
        os.path.join(case, "postProcessing", "rigidBodyMotion", "section.dat")))
    t = motion[:, 0]
    # From t = 0, the state at rest (the first time step's) until then
    grid = np.arange(0.0, t[-1] + 1e-9, run["sampleInterval"])
    series = {"Time": grid,
              "sway": np.interp(grid, t, motion[:, 1] - motion[0, 1]),
              "heave": np.interp(grid, t, motion[:, 3] - motion[0, 3]),
              "roll": np.interp(grid, t, motion[:, 6])}
    for key, spring in SPRINGS.items():
        dat = os.path.join(case, "postProcessing", "fmuConnectors", "0", spring + ".dat")
        col = postprocessing.header_column(dat, "tension")
        rows = np.array(postprocessing.read_table(dat))
        series[key] = np.interp(grid, rows[:, 0], rows[:, col])
    times, eta = postprocessing.read_gauges(case, STILL_WATER_DEPTH)
    for name in GAUGES:
        x = run["gauge." + name]
        nearest = min(eta, key=lambda g: abs(g - x))
        if abs(nearest - x) > 1e-5:
            raise SectionWavesError("no wave gauge at x = %g (%s in constant/runSettings); "
                                    "the gauges are at %s" % (
                                        x, GAUGES[name], ", ".join("%g" % g for g in sorted(eta))))
        series["eta." + name] = np.interp(grid, times, eta[nearest])
    return run, series


SERIES_COLUMNS = (["Time", "sway", "heave", "roll"] + list(SPRINGS)
                  + ["eta." + g for g in GAUGES])


def write_run(folder, run, series):
    """folder/run.dat and folder/series.dat (module docstring)."""
    postprocessing.write_kept_run(
        folder, run, series, SERIES_COLUMNS,
        "mooredSectionWaves run (python/foamfmi/sectionwaves.py): key value",
        "mooredSectionWaves response every T/%d: sway, heave (m), roll (deg), "
        "spring tensions (N), elevation at the gauges (m; x in run.dat)" % SAMPLES_PER_PERIOD)


def read_run(folder):
    """(run, series) of a folder written by write_run."""
    return postprocessing.read_kept_run(folder, SERIES_COLUMNS,
                                        ("period", "height", "rampTime", "xIn"))


# ------------------------------------------------------- the experiment --

# Columns of experiment/measured.dat (experimentRao) by the keys used here
EXPERIMENT_COLUMNS = {
    "PP": "PP", "Hindex": "H", "period": "T", "aNominal": "aNominal", "amplitude": "a",
    "nRep": "nRep", "windowPeriods": "windowPeriods", "windowDelay": "windowDelay",
    "sway": "raoSway", "heave": "raoHeave", "roll": "raoRoll",
    "tensionWeather": "raoTensionSB", "tensionLee": "raoTensionPS",
    "swayMean": "swayMean", "tensionWeatherMean": "tensionSBMean",
    "tensionLeeMean": "tensionPSMean", "wpUpAmp": "wpUpAmp",
    "swaySpread": "raoSwaySpread", "heaveSpread": "raoHeaveSpread",
    "rollSpread": "raoRollSpread", "k": "k", "amplitudeSpread": "aSpread",
}
# The window's spread of experimentRao, by the keys of QUANTITIES
for _key, _stem in (("sway", "Sway"), ("heave", "Heave"), ("roll", "Roll"),
                    ("tensionWeather", "TensionSB"), ("tensionLee", "TensionPS")):
    EXPERIMENT_COLUMNS[_key + "WindowLow"] = "rao%sWindowLow" % _stem
    EXPERIMENT_COLUMNS[_key + "WindowHigh"] = "rao%sWindowHigh" % _stem


def read_experiment(path):
    """The cases of experiment/measured.dat: [{key: value}] by the keys
    of EXPERIMENT_COLUMNS, with tensionMean (the two gauges' mean RAO)
    and drift (the mean load on the springs, SB less PS, N)."""
    names, cases = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                words = line[1:].split()
                if set(EXPERIMENT_COLUMNS.values()) <= set(words):
                    names = words
                continue
            if not line.strip():
                continue
            if names is None:
                raise SectionWavesError("%s: no header line naming the columns %s before the data"
                                        % (path, " ".join(sorted(EXPERIMENT_COLUMNS.values()))))
            values = line.split()
            if len(values) != len(names):
                raise SectionWavesError("%s: a row of %d values under a header of %d names"
                                        % (path, len(values), len(names)))
            row = {key: float(values[names.index(name)])
                   for key, name in EXPERIMENT_COLUMNS.items()}
            row["tensionMean"] = 0.5 * (row["tensionWeather"] + row["tensionLee"])
            row["drift"] = row["tensionWeatherMean"] - row["tensionLeeMean"]
            cases.append(row)
    return cases


def experiment_case(cases, period, height):
    """The case with this wave (period within 1 ms, height 2 aNominal
    within 0.1 mm), or None."""
    for row in cases:
        if abs(row["period"] - period) < 1e-3 and abs(2 * row["aNominal"] - height) < 1e-4:
            return row
    return None


# ------------------------------------------------------------ analysis --

def window(run, experiment):
    """The window: the experiment's for this wave, the same time after the
    generator's start (both 7 m before the section; in a flume of
    another length moved by the waves' travel time at the linear group
    velocity over the difference) over the same whole
    periods; without one, from the end of the ramp at the section (the
    front's travel at the linear group velocity from the generator, plus
    the ramp) over DEFAULT_PERIODS periods."""
    T = run["period"]
    cg = waves.group_velocity_of_period(T, STILL_WATER_DEPTH)
    if experiment and "windowDelay" in experiment:
        # In another flume than the experiment's, moved by the travel time
        # of the difference
        t0 = experiment["windowDelay"] + (SECTION_X - run["xIn"] - EXPERIMENT_GENERATOR) / cg
    else:
        t0 = (SECTION_X - run["xIn"]) / cg + run["rampTime"]
    n = int(round(experiment["windowPeriods"])) if experiment else DEFAULT_PERIODS
    return t0, t0 + n * T, n


def _responses(run, series, t0, t1, k0):
    """First harmonics and means over [t0, t1], roll per k0 a: {name: value}."""
    T = run["period"]
    omega = 2 * math.pi / T
    k = waves.wave_number(omega, STILL_WATER_DEPTH)
    t = series["Time"]
    fits = {name: harmonics.fit_window(t, series[name], omega, t0, t1)
            for name in SERIES_COLUMNS[1:]}
    z = [fits["eta." + g].amplitudes[0] for g in INCIDENT_GAUGES]
    x = [run["gauge." + g] for g in INCIDENT_GAUGES]
    incident, reflected = harmonics.separate_waves(z, x, k)
    a = abs(incident)
    r = {"incidentAmplitude": a, "reflectedAmplitude": abs(reflected),
         "reflectionCoefficient": abs(reflected) / a,
         "WP4Amplitude": abs(fits["eta.WP4"].amplitudes[0]),
         "downAmplitude": abs(fits["eta.down"].amplitudes[0]),
         "k": k, "k0": k0}
    for name in ("sway", "heave", "roll") + tuple(SPRINGS):
        r[name + "Amplitude"] = abs(fits[name].amplitudes[0])
        r[name + "Mean"] = fits[name].mean
    r["sway"] = r["swayAmplitude"] / a
    r["heave"] = r["heaveAmplitude"] / a
    r["roll"] = math.radians(r["rollAmplitude"]) / (k0 * a)
    for name in SPRINGS:
        r[name] = r[name + "Amplitude"] / a
        # Tared at rest, as the experiment's gauges: the change of the mean
        r[name + "Mean"] -= series[name][0]
    r["tensionMean"] = 0.5 * (r["tensionWeather"] + r["tensionLee"])
    r["drift"] = r["tensionWeatherMean"] - r["tensionLeeMean"]
    return r


def analyse(run, series, experiment=None):
    """The run's responses over the window (window()), and over
    the window shifted by one period either way (windowLow, windowHigh:
    the smallest and largest of the three): {name: value}. None when
    the run ends before the window. Roll per k0 a, k0 the experiment's
    (its docs' table: deep water), else omega^2/g."""
    omega = 2 * math.pi / run["period"]
    k0 = experiment["k"] if experiment else omega * omega / waves.G
    t0, t1, n = window(run, experiment)
    T = run["period"]
    t_end = series["Time"][-1]
    if t1 > t_end + 1e-9:
        return None
    r = _responses(run, series, t0, t1, k0)
    r.update({"windowStart": t0, "windowEnd": t1, "windowPeriods": n})
    shifted = [r]
    for shift in (-T, T):
        if t0 + shift >= series["Time"][0] and t1 + shift <= t_end + 1e-9:
            shifted.append(_responses(run, series, t0 + shift, t1 + shift, k0))
    for name, _, _ in QUANTITIES:
        r[name + ".windowLow"] = min(s[name] for s in shifted)
        r[name + ".windowHigh"] = max(s[name] for s in shifted)
    r["windowShifts"] = len(shifted) - 1
    return r


# ---------------------------------------------------------------- plots --

def experiment_runs(series_dir, experiment):
    """The measured series files (experimentRao: series/<run>.dat) of the
    experiment's case: runs 3<PP><H>_<n>."""
    if experiment is None or not os.path.isdir(series_dir):
        return []
    stem = "3%02d%d_" % (int(experiment["PP"]), int(experiment["Hindex"]))
    return sorted(os.path.join(series_dir, f) for f in os.listdir(series_dir)
                  if f.startswith(stem) and f.endswith(".dat"))


def plot_overlay(plot_dir, name, run, series, r, series_dir, experiment):
    """plot_dir/name.png: the run (plot_dir/series.dat) over the window, 5
    periods before it and one after, the window shaded, with the measured
    runs of the same wave (time after the generator's start in both):
    the elevation at WP_4 (with the section), sway, heave, roll and each
    spring's tension change from rest."""
    T = run["period"]
    t0, t1 = r["windowStart"], r["windowEnd"]
    own = os.path.join(plot_dir, "series.dat")
    col = {c: i + 1 for i, c in enumerate(SERIES_COLUMNS)}
    measured = experiment_runs(series_dir, experiment)
    panels = [("elevation at WP_4 (m)", col["eta.WP4"], 7, 0.0),
              ("sway (m)", col["sway"], 2, 0.0), ("heave (m)", col["heave"], 3, 0.0),
              ("roll (deg)", col["roll"], 4, 0.0),
              ("weather spring: tension change (N)", col["tensionWeather"], 5,
               series["tensionWeather"][0]),
              ("lee spring: tension change (N)", col["tensionLee"], 6, series["tensionLee"][0])]
    lines = ["set terminal " + plots.terminal("1000,1400"),
             "set output '%s/%s.png'" % (plot_dir, name), "set termoption noenhanced",
             "set multiplot layout %d,1 title \"Section in waves, H = %g m, T = %g s: "
             "this run (mesh factor %g) and the experiment%s; window grey\""
             % (len(panels), run["height"], T, run.get("meshFactor", float("nan")),
                "'s runs" if measured else " (none for this wave)"),
             "set grid", "set key top left opaque", "set lmargin 10",
             "set xrange [%g:%g]" % (t0 - 5 * T, t1 + T), plots.shade(t0, t1)]
    for i, (label, c_own, c_exp, tare) in enumerate(panels):
        if i == len(panels) - 1:
            lines.append("set xlabel 't after the generator starts (s)'")
        curves = ["'%s' u 1:($%d-%.9g) w l lw 1.6 lc rgb '#1f5fbf' t 'CFD'" % (own, c_own, tare)]
        curves += ["'%s' u 1:%d w l lw 1.0 dt 2 t 'run %s'"
                   % (m, c_exp, os.path.basename(m)[:-4]) for m in measured]
        lines += ['set ylabel "%s"' % label, "plot " + ", ".join(curves)]
    lines.append("unset multiplot")
    plots.gnuplot(os.path.join(plot_dir, name + ".gp"), lines)

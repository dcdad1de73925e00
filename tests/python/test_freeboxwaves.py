"""foamfmi.freeboxwaves: the fit recovers a drifting sine of known
amplitude and phase; the comparison of a synthetic run with synthetic
curves of known harmonics, on another clock, gives the clock shift and
the known ratios; the committed measured curves read back in SI units with
the experiment's period and wave amplitude; a run written and read back."""

import cmath
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from foamfmi import freeboxwaves as fb
from foamfmi import harmonics, postprocessing

EXPERIMENT = os.path.join(os.environ.get("FOAMFMI_DIR", "."), "tutorials", "freeBoxWaves",
                          "experiment", "Ren2015data")
OMEGA = 2 * math.pi / fb.PERIOD
# Synthetic responses: (mean, drift velocity, complex first harmonic,
# complex second harmonic) of surge (m), heave (m), pitch (deg) and the wave (m)
RESPONSE = {"surge": (0.05, 0.02, 0.021 * cmath.exp(-1.3j), 0.002j),
            "heave": (0.001, 0.0, 0.026 * cmath.exp(0.4j), 0.003),
            "pitch": (0.2, 0.0, 2.7 * cmath.exp(-0.35j), 0.1j),
            "wave": (0.0, 0.0, 0.02 * cmath.exp(2.0j), 0.002)}


def signal(t, q, scale=1.0):
    mean, drift, z1, z2 = RESPONSE[q]
    e = np.exp(1j * OMEGA * t)
    return mean + drift * t + np.real(scale * z1 * e + z2 * e * e)


class FitTest(unittest.TestCase):
    def test_drifting_sine(self):
        # Exact model: recovered to round-off (1e-10 of the amplitudes)
        t = np.arange(0.0, 10.0, fb.PERIOD / 32)
        mean, drift, z1, _ = RESPONSE["surge"]
        y = signal(t, "surge")
        m, v, z = fb.fit(t, y, 3.0, 3.0 + 3 * fb.PERIOD)
        self.assertAlmostEqual(m, mean + drift * (3.0 + 1.5 * fb.PERIOD), delta=1e-10)
        self.assertAlmostEqual(v, drift, delta=1e-10)
        self.assertAlmostEqual(abs(z - z1), 0.0, delta=1e-10)

    def test_too_few_samples(self):
        t = np.arange(0.0, 2.0, 0.5)
        with self.assertRaises(harmonics.FitError):
            fb.fit(t, np.sin(t), 0.0, 2.0)


def synthetic(shift, scale):
    """A run (series every T/32 to 11 s) and measured curves (every T/18,
    5 periods, the run's time less shift) of the RESPONSE harmonics; the
    run's first harmonics scaled by scale."""
    t = np.arange(0.0, 11.0, fb.PERIOD / 32)
    series = {"Time": t, "eta.1": signal(t, "wave"), "eta.3": signal(t, "wave")}
    for q in ("surge", "heave", "pitch"):
        series[q] = signal(t, q, scale)
    te = np.arange(0.0, 5 * fb.PERIOD, fb.PERIOD / 18)
    curves = {q: (te, signal(te + shift, q)) for q in RESPONSE}
    return series, curves


class CompareTest(unittest.TestCase):
    def test_known_answer(self):
        # The curves on a clock 5.3 s behind the run's: the shift is found
        # from the heave's phase (to round-off: exact harmonics), amplitudes
        # and RAOs are the scale's, the phases against heave the same, the
        # drift velocity the synthetic one
        series, curves = synthetic(5.3, 1.1)
        r = fb.compare(series, curves)
        self.assertAlmostEqual(r["clockShift"], 5.3, delta=1e-9)
        self.assertEqual(r["windowPeriods"], 3)
        self.assertAlmostEqual(r["windowStart"], fb.window_start(), delta=1e-12)
        for q in ("surge", "heave", "pitch"):
            self.assertAlmostEqual(r["%s.amplitudeError" % q], 0.1, delta=1e-9)
            self.assertAlmostEqual(r["%s.raoError" % q], 0.1, delta=1e-9)
        self.assertAlmostEqual(r["wave.amplitudeError"], 0.0, delta=1e-9)
        self.assertAlmostEqual(r["cfd.heave.amplitude"], 1.1 * 0.026, delta=1e-10)
        self.assertAlmostEqual(r["experiment.heave.rao"], 0.026 / 0.02, delta=1e-9)
        k = 2 * math.pi / fb.EXPERIMENT_WAVELENGTH
        self.assertAlmostEqual(r["experiment.pitch.rao"], math.radians(2.7) / (k * 0.02),
                               delta=1e-9)
        self.assertAlmostEqual(r["experiment.surge.phase"], math.degrees(-1.3 - 0.4), delta=1e-7)
        self.assertAlmostEqual(r["pitch.phaseError"], 0.0, delta=1e-7)
        self.assertAlmostEqual(r["cfd.surge.drift"], 0.02, delta=1e-10)
        self.assertAlmostEqual(r["experiment.surge.drift"], 0.02, delta=1e-10)
        lines = fb.table_lines(r)
        self.assertIn("| heave amplitude (m) | 0.026 | 0.0286 | +10.0 % |", lines)

    def test_window_starts_with_the_curves(self):
        # Curves on a clock 6.2 s behind the run's: of the shifts that put
        # the heaves in phase (5.0 + 1.2 j s) the nearest to the waves'
        # arrival at the box (5.78 s) is 6.2 s; the curves start at 6.2 s on
        # the run's clock, and so does the window
        series, curves = synthetic(6.2, 1.0)
        r = fb.compare(series, curves)
        self.assertAlmostEqual(r["clockShift"], 6.2, delta=1e-9)
        self.assertAlmostEqual(r["windowStart"], 6.2, delta=1e-9)
        self.assertEqual(r["windowPeriods"], 3)
        self.assertAlmostEqual(r["heave.amplitudeError"], 0.0, delta=1e-9)
        # A run that ends 2.5 periods after it: 2 periods compared
        short = {c: v[series["Time"] <= 6.2 + 2.5 * fb.PERIOD] for c, v in series.items()}
        self.assertEqual(fb.compare(short, curves)["windowPeriods"], 2)

    def test_short_run(self):
        series, curves = synthetic(5.3, 1.0)
        short = {c: v[series["Time"] < fb.window_start() + 0.5 * fb.PERIOD]
                 for c, v in series.items()}
        self.assertIsNone(fb.compare(short, curves))


class ExperimentTest(unittest.TestCase):
    def test_committed_curves(self):
        for height in (0.04, 0.10):
            curves = fb.read_experiment(EXPERIMENT, height)
            self.assertEqual(sorted(curves), sorted(fb.QUANTITIES))
            # About five periods each, from t = 0 (within the 0.2 s the
            # digitised surge of H = 0.04 m starts late)
            for t, _ in curves.values():
                self.assertLess(t[0], 0.21)
                self.assertGreater(t[-1], 4.9 * fb.PERIOD)
            # The wave's period is the experiment's 1.2 s: the mean
            # up-crossing interval within 1 % (the digitised time axis)
            period, n = harmonics.upcrossing_period(*curves["wave"], 0.0)
            self.assertGreaterEqual(n, 3)
            self.assertAlmostEqual(period, fb.PERIOD, delta=0.01 * fb.PERIOD)
        # H = 0.04 m, H/L = 0.021, nearly linear: the first harmonic of the
        # elevation is H/2 within 2 % (digitisation and the third harmonic,
        # (k a)^2 = 0.4 %), which checks the scale eta/d x 0.4 m
        t, eta = fb.read_experiment(EXPERIMENT, 0.04)["wave"]
        z = fb.fit(t, eta, 0.0, 4 * fb.PERIOD)[2]
        self.assertAlmostEqual(abs(z), 0.02, delta=0.02 * 0.02)

    def test_unmeasured_height(self):
        with self.assertRaisesRegex(fb.FreeBoxError, "no measured curves for a wave height of 0.06"):
            fb.experiment_name(0.06)


class RunFilesTest(unittest.TestCase):
    def test_round_trip(self):
        series, _ = synthetic(5.3, 1.0)
        run = {"height": 0.04, "meshFactor": 1.0, "endTime": 10.584, "coupling": "addedMass",
               "nProcs": 1.0, "cells": 11796, "commit": "test"}
        with tempfile.TemporaryDirectory() as d:
            fb.write_run(d, run, series)
            run2, series2 = fb.read_run(d)
        self.assertEqual(run2["coupling"], "addedMass")
        self.assertEqual(run2["meshFactor"], 1.0)
        # A run kept before the pitch inertia was a setting had FloatStepper's
        self.assertNotIn("pitchInertia", run)
        self.assertEqual(run2["pitchInertia"], 0.15106368)
        self.assertEqual(run2["centreOfMassHeight"], 0.0)
        # and the short morphing
        self.assertEqual(run2["morphing"], "short")
        # series.dat keeps 7 digits
        for c in fb.SERIES_COLUMNS:
            np.testing.assert_allclose(series2[c], series[c], rtol=1e-6, atol=1e-9)

    def test_missing_column(self):
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "run.dat"), "w") as f:
                f.write("height 0.04\nmeshFactor 1\nendTime 9\ncoupling stock\nnProcs 1\n")
            with open(os.path.join(d, "series.dat"), "w") as f:
                f.write("# Time surge heave\n0 0 0\n")
            with self.assertRaisesRegex(postprocessing.PostProcessingError, "no column pitch"):
                fb.read_run(d)


class KeptRunsTest(unittest.TestCase):
    def test_mesh_study(self):
        # Heave amplitudes converging as h^2 on F = 2, 1.414, 1 (h = 1/F):
        # the GCI with p = 2 (Celik et al.: 1.25 |phi1 - phi2|/(r^2 - 1))
        rows = []
        for f in (1.0, 2.0, 1.414):
            a = 0.026 + 0.004 / f ** 2
            rows.append(({"meshFactor": f}, {"cfd.%s.amplitude" % q: a for q in fb.QUANTITIES}))
        u, how, phi, factors = fb.mesh_study(rows)["heave"]
        self.assertEqual(how, "GCI")
        self.assertEqual(factors, [2.0, 1.414, 1.0])
        r = 2.0 / 1.414
        self.assertAlmostEqual(u, 1.25 * abs(phi[0] - phi[1]) / (r ** 2 - 1), delta=1e-9)
        self.assertEqual(fb.mesh_study(rows[:2]), {})

    def test_report(self):
        # boxResponse -report on three kept synthetic runs (the script and
        # the committed curves copied beside them), a fourth of another
        # pitch inertia and a fifth of the long morphing: every run
        # compared, the heave's 10 % error in each table and the table at a
        # glance, and the mesh study of the three that differ only in the
        # mesh
        top = os.environ.get("FOAMFMI_DIR", ".")
        with tempfile.TemporaryDirectory() as d:
            shutil.copy(os.path.join(top, "tutorials", "freeBoxWaves", "boxResponse"), d)
            shutil.copytree(EXPERIMENT, os.path.join(d, "experiment", "Ren2015data"))
            for f in (1.0, 1.414, 2.0):
                series, _ = synthetic(5.3, 1.1)
                for q in ("surge", "heave", "pitch"):
                    series[q] = series[q] * (1 + 0.01 / f)
                run = {"height": 0.04, "meshFactor": f, "endTime": 11.0,
                       "coupling": "addedMass", "nProcs": 1.0, "commit": "test"}
                fb.write_run(os.path.join(d, "results", "F%g" % f), run, series)
                if f == 1.0:
                    fb.write_run(os.path.join(d, "results", "F1_long"),
                                 dict(run, morphing="long"), series)
                    run["pitchInertia"] = 0.13
                    fb.write_run(os.path.join(d, "results", "F1_I0.13"), run, series)
            out = subprocess.run([sys.executable, os.path.join(d, "boxResponse"), "-report",
                                  "-no-plot"], capture_output=True, text=True)
            self.assertEqual(out.returncode, 0, out.stderr)
            with open(os.path.join(d, "results", "report.md")) as f:
                report = f.read()
            self.assertTrue(os.path.isfile(os.path.join(d, "results", "F2", "boxResponse.dat")))
        self.assertEqual(report.count("| heave amplitude (m) |"), 5)
        self.assertEqual(report.count("## Numerical uncertainty"), 1)
        self.assertIn("## Numerical uncertainty, H = 0.04 m, addedMass coupling, short morphing, "
                      "pitch inertia 0.15106368 kg m^2, centre of mass 0 m above the box's centre",
                      report)
        glance = [line for line in report.splitlines() if line.startswith("| F1_I0.13 |")]
        self.assertEqual(len(glance), 1)
        self.assertIn("| 0.13 |", glance[0])
        self.assertIn("| short |", glance[0])
        long_row = [line for line in report.splitlines() if line.startswith("| F1_long |")]
        self.assertIn("| long |", long_row[0])
        self.assertIn("addedMass coupling, long morphing", report.split("## F1_long")[1])
        # Its heave RAO's error is its own table's
        own = report.split("## F1_I0.13")[1]
        heave_rao = [line for line in own.splitlines() if line.startswith("| heave RAO")][0]
        self.assertEqual(glance[0].split("|")[9].strip(), heave_rao.split("|")[4].strip())
        self.assertIn("| heave (m) | 2 / 1.414 / 1 |", report)
        # The wave, the same on the three (to series.dat's 7 digits): its
        # U_num below 1e-6 of it
        wave = [line for line in report.splitlines() if line.startswith("| wave (m) | 2 /")]
        self.assertEqual(len(wave), 1)
        self.assertIn("| 0.02 / 0.02 / 0.02 |", wave[0])
        self.assertLess(float(wave[0].split("|")[4].split()[0]), 2e-8)


if __name__ == "__main__":
    unittest.main()

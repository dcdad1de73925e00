"""foamfmi.sectionwaves: a synthetic run of known harmonics written,
read back and analysed gives its RAOs with the experiment's definitions."""

import cmath
import math
import os
import tempfile
import unittest

import numpy as np

from foamfmi import sectionwaves, waves


def synthetic_run():
    T, H = 1.158, 0.024
    omega = 2 * math.pi / T
    k = waves.wave_number(omega, 1.0)
    run = {"period": T, "height": H, "rampTime": 5 * T, "xIn": -7.0, "meshFactor": 0.5,
           "gauge.separation2": -1.5 - 0.25 * 2 * math.pi / k,
           "gauge.separation1": -1.5 - 0.1 * 2 * math.pi / k,
           "gauge.WP4": -1.5, "gauge.down": 1.6, "commit": "test"}
    t = np.arange(0.0, 25.0, T / sectionwaves.SAMPLES_PER_PERIOD)
    incident, reflected = 0.0118 * cmath.exp(0.3j), 0.0021 * cmath.exp(-0.8j)
    e = np.exp(1j * omega * t)
    series = {"Time": t,
              "sway": 0.002 + 0.004 * np.cos(omega * t + 0.2),
              "heave": 0.018 * np.sin(omega * t) + 0.001 * np.cos(2 * omega * t),
              "roll": 6.5 * np.cos(omega * t - 1.0),
              "tensionWeather": 10.0 + 0.05 + 0.12 * np.cos(omega * t),
              "tensionLee": 10.0 - 0.03 + 0.10 * np.cos(omega * t + math.pi),
              "eta.down": 0.01 * np.cos(omega * t)}
    for g in sectionwaves.INCIDENT_GAUGES:
        x = run["gauge." + g]
        z = incident * cmath.exp(-1j * k * x) + reflected * cmath.exp(1j * k * x)
        series["eta." + g] = np.real(z * e)
    # At rest before the waves: the tare of the tensions is the first sample
    series["tensionWeather"][0] = 10.0
    series["tensionLee"][0] = 10.0
    return run, series, abs(incident), abs(reflected)


class AnalysisTest(unittest.TestCase):
    def test_raos_of_known_harmonics(self):
        run, series, a, ar = synthetic_run()
        with tempfile.TemporaryDirectory() as d:
            sectionwaves.write_run(d, run, series)
            self.assertTrue(os.path.isfile(os.path.join(d, "series.dat")))
            run2, series2 = sectionwaves.read_run(d)
        self.assertEqual(run2["commit"], "test")
        # Roll per the experiment's k0 (its docs' table: 3.0 rad/m here)
        k0 = 3.0
        r = sectionwaves.analyse(run2, series2, {"windowPeriods": 6, "k": k0})
        # series.dat keeps 7 digits: the harmonics come back within a few
        # 1e-7 of their size, the separated waves within that of the gauges
        self.assertAlmostEqual(r["incidentAmplitude"], a, delta=1e-8)
        self.assertAlmostEqual(r["reflectedAmplitude"], ar, delta=1e-8)
        self.assertAlmostEqual(r["sway"], 0.004 / a, delta=1e-5)
        self.assertAlmostEqual(r["swayMean"], 0.002, delta=1e-8)
        self.assertAlmostEqual(r["heave"], 0.018 / a, delta=1e-5)
        self.assertAlmostEqual(r["roll"], math.radians(6.5) / (k0 * a), delta=1e-5)
        self.assertAlmostEqual(r["tensionWeather"], 0.12 / a, delta=1e-4)
        self.assertAlmostEqual(r["tensionLee"], 0.10 / a, delta=1e-4)
        self.assertAlmostEqual(r["tensionWeatherMean"], 0.05, delta=1e-6)
        self.assertAlmostEqual(r["tensionLeeMean"], -0.03, delta=1e-6)
        self.assertAlmostEqual(r["drift"], 0.08, delta=1e-6)
        # Steady harmonics: the shifted windows give the same RAOs
        self.assertEqual(r["windowShifts"], 2)
        self.assertAlmostEqual(r["roll.windowHigh"], r["roll.windowLow"], delta=1e-5)
        # Without the experiment's window delay: travel from 7 m at the
        # linear group velocity, then the ramp
        cg = waves.group_velocity_of_period(run["period"], 1.0)
        self.assertAlmostEqual(r["windowStart"], 7.0 / cg + 5 * run["period"], places=12)
        # With it: the experiment's window after the generator's start
        r = sectionwaves.analyse(run2, series2, {"windowPeriods": 5, "k": k0,
                                                 "windowDelay": 13.5})
        self.assertEqual(r["windowStart"], 13.5)
        self.assertAlmostEqual(r["windowEnd"], 13.5 + 5 * run["period"], places=12)

    def test_a_run_too_short_has_no_raos(self):
        run, series, _, _ = synthetic_run()
        short = {key: value[:100] for key, value in series.items()}
        self.assertIsNone(sectionwaves.analyse(run, short, None))

    def test_without_experiment_roll_per_deep_water_k(self):
        run, series, a, _ = synthetic_run()
        r = sectionwaves.analyse(run, series, None)
        omega = 2 * math.pi / run["period"]
        self.assertEqual(r["windowPeriods"], sectionwaves.DEFAULT_PERIODS)
        self.assertAlmostEqual(r["roll"], math.radians(6.5) / (omega ** 2 / 9.81 * a),
                               delta=1e-9)


if __name__ == "__main__":
    unittest.main()

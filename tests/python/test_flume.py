"""foamfmi.flume: the incident and reflected waves along a line of gauges
from synthetic elevations, the loss per metre, the window, the summary per
the calibrated amplitude and a kept run read back."""
import cmath
import math
import tempfile
import unittest

import numpy as np

from foamfmi import flume, waves


def elevations(period, xs, incident, reflected, times, decay=0.0):
    """eta {x: series}: an incident wave Z_I exp(i(wt - kx)) whose amplitude
    falls as exp(-decay x) and a reflected wave Z_R exp(i(wt + kx))."""
    omega = 2 * math.pi / period
    k = waves.wave_number(omega, flume.STILL_WATER_DEPTH)
    t = np.asarray(times)
    return {x: ((incident * math.exp(-decay * x) * cmath.exp(-1j * k * x)
                 + reflected * cmath.exp(1j * k * x)) * np.exp(1j * omega * t)).real
            for x in xs}


class Separation(unittest.TestCase):
    period = 0.802
    xs = [-0.25 * i for i in range(9, -1, -1)]  # -2.25 ... 0: spacings L/4 to L at L = 1 m

    def test_incident_and_reflected_at_every_gauge(self):
        times = np.arange(0.0, 12 * self.period, self.period / 40)
        eta = elevations(self.period, self.xs, 0.0119 * cmath.exp(0.4j),
                         0.0011 * cmath.exp(-2.1j), times)
        rows = flume.analyse(self.period, times, eta, times[0], times[-1])
        self.assertEqual([r["x"] for r in rows], sorted(self.xs))
        for r in rows:
            # (the decay estimated from the gauges' amplitudes, which the
            # reflected wave modulates: not quite 0)
            self.assertAlmostEqual(r["incident"], 0.0119, delta=1e-6)
            self.assertAlmostEqual(r["reflected"], 0.0011, delta=1e-6)
            self.assertAlmostEqual(r["mean"], 0.0, delta=1e-12)
            self.assertLess(r["second"], 1e-12)
        # The sum varies along the flume between 0.0108 and 0.0130
        amplitudes = [r["amplitude"] for r in rows]
        self.assertLess(min(amplitudes), 0.0119)
        self.assertGreater(max(amplitudes), 0.0119)

    def test_a_decaying_incident_wave(self):
        times = np.arange(0.0, 12 * self.period, self.period / 40)
        eta = elevations(self.period, self.xs, 0.0119, 0.0004 * cmath.exp(1.3j), times,
                         decay=0.05)
        rows = flume.analyse(self.period, times, eta, times[0], times[-1])
        for r in rows:
            self.assertAlmostEqual(r["incident"], 0.0119 * math.exp(-0.05 * r["x"]), delta=2e-5)
            self.assertAlmostEqual(r["reflected"], 0.0004, delta=2e-5)

    def test_two_gauges_are_enough_and_one_is_refused(self):
        k = waves.wave_number(2 * math.pi / self.period, flume.STILL_WATER_DEPTH)
        x = [0.0, 0.3]
        z = [0.01 * cmath.exp(-1j * k * s) for s in x]
        incident, reflected = flume.separate_along(x, z, k)
        self.assertAlmostEqual(abs(incident[1]), 0.01, delta=1e-12)
        self.assertAlmostEqual(abs(reflected[0]), 0.0, delta=1e-12)
        with self.assertRaises(flume.FlumeError):
            flume.separate_along([0.0], [0.01], k)

    def test_loss_per_metre_of_an_exponential_decay(self):
        x = [-2.0, -1.5, -1.0, 0.0]
        a = [0.012 * math.exp(-0.1 * s) for s in x]
        self.assertAlmostEqual(flume.decay_per_metre(x, a), 1 - math.exp(-0.1), delta=1e-12)
        self.assertTrue(math.isnan(flume.decay_per_metre([0.0], [0.01])))


class WindowAndSummary(unittest.TestCase):
    def test_the_experiments_window_moves_with_the_generator(self):
        exp = {"windowDelay": 15.0, "windowPeriods": 18}
        cg = waves.group_velocity_of_period(0.802, flume.STILL_WATER_DEPTH)
        t0, t1, n = flume.window(0.802, -2.5, 4.01, exp)
        self.assertAlmostEqual(t0, 15.0 - 4.5 / cg, delta=1e-12)
        self.assertEqual(n, flume.MAX_WINDOW_PERIODS)
        self.assertAlmostEqual(t1 - t0, n * 0.802, delta=1e-12)
        t0, _, n = flume.window(0.802, -7.0, 4.01, {"windowDelay": 15.0, "windowPeriods": 1})
        self.assertEqual((t0, n), (15.0, 1))
        t0, _, _ = flume.window(0.802, -2.5, 4.01)
        self.assertAlmostEqual(t0, 2.5 / cg + 4.01, delta=1e-12)

    def test_summary_per_the_calibrated_amplitude(self):
        rows = [{"x": x, "amplitude": 0.012 * math.exp(-0.05 * (x + 2)), "reflected": 0.0006}
                for x in (-2.0, -1.5, -1.0, -0.5, 0.0)]
        s = flume.summary(rows, 0.012)
        self.assertAlmostEqual(s["first"], 1.0, delta=1e-12)
        self.assertAlmostEqual(s["WP4"], math.exp(-0.025), delta=1e-12)
        self.assertAlmostEqual(s["last"], math.exp(-0.1), delta=1e-12)
        self.assertAlmostEqual(s["lossPerMetre"], 1 - math.exp(-0.05), delta=1e-12)
        self.assertAlmostEqual(s["reflection"], 0.0006 / rows[-1]["amplitude"], delta=1e-12)
        with self.assertRaises(flume.FlumeError):
            flume.summary(rows[2:], 0.012)

    def test_a_kept_run_reads_back(self):
        rows = [{"x": x, "amplitude": 0.01, "incident": 0.0101, "reflected": 0.0002,
                 "second": 0.0003, "mean": -1e-5} for x in (0.0, -0.25)]
        run = {"period": 0.802, "cells": 10207, "ddt": "CrankNicolson_0.5"}
        with tempfile.TemporaryDirectory() as folder:
            flume.write_kept(folder, run, rows)
            back, back_rows = flume.read_kept(folder)
        self.assertEqual(back, run)
        self.assertEqual([r["x"] for r in back_rows], [-0.25, 0.0])
        self.assertAlmostEqual(back_rows[1]["incident"], 0.0101, delta=1e-12)


if __name__ == "__main__":
    unittest.main()

"""foamfmi.harmonics: a fit recovers a known amplitude and phase from a
synthetic signal with noise; reflection from two gauges; up-crossings."""
import cmath
import math
import random
import unittest

from foamfmi import harmonics


def signal(t, omega, mean, z1, z2):
    return (mean + (z1 * cmath.exp(1j * omega * t)).real
            + (z2 * cmath.exp(2j * omega * t)).real)


class Fit(unittest.TestCase):
    omega = 2 * math.pi / 1.5
    z1 = 0.025 * cmath.exp(0.7j)
    z2 = 0.003 * cmath.exp(-1.9j)

    def test_exact_signal(self):
        t = [0.01 * i for i in range(900)]
        y = [signal(s, self.omega, 0.12, self.z1, self.z2) for s in t]
        f = harmonics.fit(t, y, self.omega)
        self.assertAlmostEqual(f.mean, 0.12, delta=1e-14)
        self.assertAlmostEqual(abs(f.amplitudes[0] - self.z1), 0.0, delta=1e-14)
        self.assertAlmostEqual(abs(f.amplitudes[1] - self.z2), 0.0, delta=1e-14)
        self.assertLess(f.rms, 1e-14)
        self.assertEqual(f.samples, 900)

    def test_noisy_signal_amplitude_and_phase(self):
        # 10 periods at 100 samples per period, noise of 2 mm: the
        # amplitude's standard error is sigma sqrt(2/N) = 0.09 mm
        rng = random.Random(20261126)
        sigma = 0.002
        t = [0.015 * i for i in range(1000)]
        y = [signal(s, self.omega, -0.01, self.z1, self.z2) + rng.gauss(0, sigma) for s in t]
        mean, amplitude = harmonics.first_harmonic(t, y, self.omega, t[0], t[-1])
        f = harmonics.fit(t, y, self.omega)
        self.assertAlmostEqual(amplitude, 0.025, delta=4 * sigma * math.sqrt(2 / len(t)))
        self.assertAlmostEqual(cmath.phase(f.amplitudes[0]), 0.7, delta=0.02)
        self.assertAlmostEqual(mean, -0.01, delta=4 * sigma / math.sqrt(len(t)))
        self.assertAlmostEqual(f.rms, sigma, delta=0.1 * sigma)

    def test_window_and_too_few_samples(self):
        t = [0.1 * i for i in range(100)]
        y = [signal(s, self.omega, 0.0, self.z1, 0) for s in t]
        mean, amplitude = harmonics.first_harmonic(t, y, self.omega, 3.0, 6.0)
        self.assertAlmostEqual(amplitude, abs(self.z1), delta=1e-14)
        self.assertEqual(len(harmonics.in_window(t, y, 3.0, 6.0)[0]), 31)
        with self.assertRaisesRegex(harmonics.FitError, "only 6 samples in the window 3-3.5 s"):
            harmonics.first_harmonic(t, y, self.omega, 3.0, 3.5)


class Reflection(unittest.TestCase):
    def test_incident_and_reflected_waves_from_two_gauges(self):
        k = 2 * math.pi / 2.826
        zi, zr = 0.025 * cmath.exp(0.3j), 0.004 * cmath.exp(-1.2j)

        def at(x):
            return zi * cmath.exp(-1j * k * x) + zr * cmath.exp(1j * k * x)

        x1, x2 = 3.03, 3.51
        i, r = harmonics.incident_reflected(at(x1), at(x2), x1, x2, k)
        self.assertAlmostEqual(abs(i - zi), 0.0, delta=1e-15)
        self.assertAlmostEqual(abs(r - zr), 0.0, delta=1e-15)

    def test_least_squares_separation_from_four_gauges(self):
        # An incident wave, a reflected one and a disturbance the two-wave
        # model does not hold (1.2e-4 at each gauge, 1 % of the incident):
        # four gauges give the two waves within the pseudo-inverse's norm
        # (0.64 for these spacings) times the disturbance's norm (2.4e-4),
        # 1.6e-4; without it, exactly (rounding)
        k = 3.1
        zi, zr = 0.012 * cmath.exp(0.4j), 0.003 * cmath.exp(-1.1j)
        xs = [-2.3, -1.9, -1.5, -1.37]
        exact = [zi * cmath.exp(-1j * k * x) + zr * cmath.exp(1j * k * x) for x in xs]
        i, r = harmonics.separate_waves(exact, xs, k)
        self.assertAlmostEqual(abs(i - zi), 0.0, delta=1e-15)
        self.assertAlmostEqual(abs(r - zr), 0.0, delta=1e-15)
        noisy = [z + 1.2e-4 * cmath.exp(1j * (7 * n)) for n, z in enumerate(exact)]
        i, r = harmonics.separate_waves(noisy, xs, k)
        self.assertLess(abs(i - zi), 1.6e-4)
        self.assertLess(abs(r - zr), 1.6e-4)
        # Two gauges: Goda and Suzuki's exact solution
        i2, r2 = harmonics.separate_waves(noisy[:2], xs[:2], k)
        g, h = harmonics.incident_reflected(noisy[0], noisy[1], xs[0], xs[1], k)
        self.assertAlmostEqual(abs(i2 - g), 0.0, delta=1e-15)
        self.assertAlmostEqual(abs(r2 - h), 0.0, delta=1e-15)
        with self.assertRaises(ValueError):
            harmonics.separate_waves(exact[:1], xs[:1], k)


class Upcrossings(unittest.TestCase):
    def test_period_of_a_sine(self):
        t = [0.01 * i for i in range(1001)]
        y = [0.3 + math.sin(2 * math.pi * s / 0.8 + 0.1) for s in t]
        period, n = harmonics.upcrossing_period(t, y, 1.0)
        self.assertAlmostEqual(period, 0.8, delta=1e-3)
        self.assertEqual(n, 10)

    def test_too_short(self):
        period, n = harmonics.upcrossing_period([0, 1, 2], [0, 1, 0], 0)
        self.assertTrue(math.isnan(period))
        self.assertEqual(n, 0)


class FreeDecay(unittest.TestCase):
    """A damped mode, as a floating body's free heave after release."""
    period, zeta, amplitude, mean = 1.15, 0.09, 0.004, -0.0007

    def record(self, sigma_noise, t0=0.3, t1=5.0, dt=0.047):
        rng = random.Random(20261207)
        wd = 2 * math.pi / self.period
        sigma = self.zeta * wd / math.sqrt(1 - self.zeta ** 2)
        t = [t0 + dt * i for i in range(int((t1 - t0) / dt) + 1)]
        y = [self.mean + self.amplitude * math.exp(-sigma * (s - t0))
             * math.cos(wd * (s - t0) + 0.4) + rng.gauss(0, sigma_noise) for s in t]
        return t, y

    def test_exact_record(self):
        t, y = self.record(0)
        d = harmonics.free_decay(t, y, t[0], t[-1])
        self.assertAlmostEqual(d.period, self.period, delta=1e-9)
        self.assertAlmostEqual(d.damping_ratio, self.zeta, delta=1e-9)
        self.assertAlmostEqual(d.amplitude, self.amplitude, delta=1e-12)
        self.assertAlmostEqual(d.mean, self.mean, delta=1e-12)
        self.assertLess(d.rms, 1e-12)

    def test_noisy_record(self):
        # Noise of 0.1 mm (about the kept runs' residual) on a 4 mm
        # decay sampled every 0.047 s: the period within 1 % and the
        # damping ratio within 0.01, several times the fit's scatter
        # over seeds
        t, y = self.record(1e-4)
        d = harmonics.free_decay(t, y, t[0], t[-1])
        self.assertAlmostEqual(d.period, self.period, delta=0.01 * self.period)
        self.assertAlmostEqual(d.damping_ratio, self.zeta, delta=0.01)
        self.assertAlmostEqual(d.rms, 1e-4, delta=3e-5)

    def test_a_lightly_damped_faster_mode(self):
        # The other kind of record: a shorter period, hardly damped
        self.period, self.zeta = 0.87, 0.014
        t, y = self.record(0)
        d = harmonics.free_decay(t, y, t[0], t[-1])
        self.assertAlmostEqual(d.period, 0.87, delta=1e-9)
        self.assertAlmostEqual(d.damping_ratio, 0.014, delta=1e-9)

    def test_no_oscillation(self):
        t = [0.1 * i for i in range(50)]
        with self.assertRaises(harmonics.FitError):
            harmonics.free_decay(t, [math.exp(-s) for s in t], 0, 5)


if __name__ == "__main__":
    unittest.main()

"""foamfmi.waves: the dispersion relation in its deep- and shallow-water
limits against their closed forms, the group velocity's limits, Stokes II."""
import math
import unittest

from foamfmi import waves

G = 9.81


class DispersionRelation(unittest.TestCase):
    def test_deep_water_is_omega_squared_over_g(self):
        # kh = 4 pi^2/(g T^2) h: T = 1 s in 50 m of water, kh = 201
        omega = 2 * math.pi / 1.0
        k = waves.wave_number(omega, 50.0)
        self.assertAlmostEqual(k / (omega * omega / G), 1.0, delta=1e-14)

    def test_shallow_water_is_omega_over_sqrt_gh(self):
        # T = 100 s in 0.1 m of water: kh = 0.0063; k = omega/sqrt(g h)
        # (1 + (kh)^2/6 + O(kh)^4)
        h, omega = 0.1, 2 * math.pi / 100.0
        k = waves.wave_number(omega, h)
        k0 = omega / math.sqrt(G * h)
        self.assertLess(k0 * h, 0.01)
        self.assertAlmostEqual(k / k0, 1 + (k0 * h) ** 2 / 6, delta=1e-8)

    def test_satisfies_the_relation_between_the_limits(self):
        for period in (0.5, 1.0, 1.5, 3.0, 10.0, 30.0):
            for depth in (0.05, 0.5, 1.0, 20.0):
                omega = 2 * math.pi / period
                k = waves.wave_number(omega, depth)
                self.assertAlmostEqual(G * k * math.tanh(k * depth) / omega ** 2, 1.0,
                                       delta=1e-14, msg="T = %g s, h = %g m" % (period, depth))

    def test_other_gravity(self):
        omega, h, g = 4.0, 0.5, 9.80665
        k = waves.wave_number(omega, h, g)
        self.assertAlmostEqual(g * k * math.tanh(k * h), omega ** 2, delta=1e-13)

    def test_wave_tank_wavelength(self):
        # tutorials/waveTank: T = 1.5 s in 0.5 m of water, L = 2.826 m
        self.assertAlmostEqual(waves.wavelength(2 * math.pi / 1.5, 0.5), 2.826, delta=5e-4)

    def test_rejects_what_has_no_wave(self):
        for omega, depth in ((0.0, 1.0), (1.0, 0.0), (-1.0, 1.0)):
            with self.assertRaises(ValueError):
                waves.wave_number(omega, depth)


class GroupVelocity(unittest.TestCase):
    def test_deep_water_is_half_the_phase_speed(self):
        omega = 2 * math.pi
        k = waves.wave_number(omega, 50.0)
        self.assertAlmostEqual(waves.group_velocity(omega, k, 50.0), 0.5 * omega / k,
                               delta=1e-12)

    def test_deep_water_beyond_sinh_range(self):
        omega = 20.0
        k = waves.wave_number(omega, 1000.0)
        self.assertEqual(waves.group_velocity(omega, k, 1000.0), 0.5 * omega / k)

    def test_shallow_water_is_sqrt_gh(self):
        h = 0.1
        cg = waves.group_velocity_of_period(100.0, h)
        self.assertAlmostEqual(cg / math.sqrt(G * h), 1.0, delta=1e-4)


class Stokes2(unittest.TestCase):
    def test_deep_water_second_harmonic_is_k_a_squared_over_2(self):
        a, k = 0.02, 4.0
        self.assertAlmostEqual(waves.stokes2_second_harmonic(a, k, 50.0), 0.5 * k * a * a,
                               delta=1e-15)


if __name__ == "__main__":
    unittest.main()

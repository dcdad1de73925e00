"""foamfmi.uncertainty against the worked example of Celik et al. (2008)
and against an exact power law."""

import unittest

from foamfmi import uncertainty


class GridConvergenceTest(unittest.TestCase):
    def test_celik_worked_example(self):
        # Celik et al. (2008), Table 1, column phi = 1: N = 18000, 8000,
        # 4500 cells in 2D (h ~ N^-1/2: r21 = 1.5, r32 = 1.333), phi =
        # 6.063, 5.972, 5.863; published p = 1.53, phi_ext = 6.1685,
        # e_a = 1.5 %, e_ext = 1.7 %, GCI = 2.2 %. Tolerances: the
        # table's rounding (3 digits of p, 5 of phi_ext, 2 of the percents)
        h = [n ** -0.5 for n in (18000, 8000, 4500)]
        g = uncertainty.grid_convergence((6.063, 5.972, 5.863), h)
        self.assertAlmostEqual(g.p, 1.53, delta=0.005)
        self.assertAlmostEqual(g.extrapolated, 6.1685, delta=0.00005)
        self.assertAlmostEqual(100 * g.approximate_error, 1.5, delta=0.05)
        self.assertAlmostEqual(100 * g.extrapolated_error, 1.7, delta=0.05)
        self.assertAlmostEqual(100 * g.gci, 2.2, delta=0.05)
        self.assertFalse(g.oscillatory)

    def test_exact_power_law(self):
        # phi(h) = 2 + 0.3 h^1.7 on unequal ratios: the procedure returns
        # the order and the limit exactly (to the iteration's 1e-12)
        h = (0.01, 0.014, 0.021)
        phi = [2 + 0.3 * x ** 1.7 for x in h]
        g = uncertainty.grid_convergence(phi, h)
        self.assertAlmostEqual(g.p, 1.7, places=8)
        self.assertAlmostEqual(g.extrapolated, 2.0, places=12)

    def test_refusals(self):
        with self.assertRaises(uncertainty.ConvergenceError):
            uncertainty.grid_convergence((1, 2, 3), (0.2, 0.1, 0.3))
        with self.assertRaises(uncertainty.ConvergenceError):
            uncertainty.grid_convergence((1, 1, 3), (0.1, 0.2, 0.3))
        # Differences equal and opposite: an apparent order of 0, from
        # which nothing extrapolates (was a division by zero)
        with self.assertRaisesRegex(uncertainty.ConvergenceError, "apparent order 0"):
            uncertainty.grid_convergence((1.0, 1.1, 1.0), (1, 2 ** 0.5, 2))

    def test_numerical_uncertainty(self):
        h = [n ** -0.5 for n in (18000, 8000, 4500)]
        u, g, how = uncertainty.numerical_uncertainty((6.063, 5.972, 5.863), h)
        self.assertEqual(how, "GCI")
        self.assertAlmostEqual(u, g.gci * 6.063, places=12)
        # Oscillating: three times the range (0.0093 here)
        u, g, how = uncertainty.numerical_uncertainty((0.5721, 0.5739, 0.5646), (2, 2.6, 3.38))
        self.assertEqual(how, "3 x range")
        self.assertTrue(g.oscillatory)
        self.assertAlmostEqual(u, 3 * 0.0093, places=12)
        # Monotonic but an order of 0.15: three times the range
        u, g, how = uncertainty.numerical_uncertainty((1.58, 1.518, 1.457), (2, 2.6, 3.38))
        self.assertEqual(how, "3 x range")
        self.assertLess(g.p, uncertainty.ORDER_RANGE[0])
        self.assertAlmostEqual(u, 3 * 0.123, places=12)

    def test_standard_uncertainties(self):
        # V&V 20's conversion of a GCI (Fs 1.25) to u_num
        self.assertAlmostEqual(uncertainty.standard_numerical_uncertainty(1.15), 1.0, places=15)
        # A uniform distribution over 46.22-46.8 kg: 0.29/sqrt(3)
        self.assertAlmostEqual(uncertainty.uniform_standard_uncertainty(46.8, 46.22),
                               0.29 / 3 ** 0.5, places=12)
        self.assertAlmostEqual(uncertainty.input_uncertainty([0.3, -0.4]), 0.5, places=15)
        self.assertEqual(uncertainty.input_uncertainty([]), 0.0)

    def test_validation_uncertainty(self):
        e, u = uncertainty.validation(1.1, 1.0, 0.03, 0.04, 0.0)
        self.assertAlmostEqual(e, 0.1, places=15)
        self.assertAlmostEqual(u, 0.05, places=15)


if __name__ == "__main__":
    unittest.main()

"""foamfmi.catenary: the closed form's closure, its limits, and the moored
box's line at rest (tutorials/mooredBoxWaves/README.md)."""
import math
import unittest

from foamfmi import catenary


class Catenary(unittest.TestCase):
    def test_closure_touchdown_and_suspended(self):
        for x, z in ((1.32, 0.43), (1.38, 0.40), (1.45, 0.30)):
            H, V = catenary.tensions(x, z, 1.455, 0.4927, 29.0)
            xs, zs = catenary.fairlead_position(H, V, 1.455, 0.4927, 29.0)
            self.assertAlmostEqual(xs, x, delta=1e-12)
            self.assertAlmostEqual(zs, z, delta=1e-12)

    def test_inextensible_suspended_line(self):
        # EA -> infinity, the whole line off the seabed: the catenary of
        # parameter a = H/w between two points x apart and z above each
        # other has the length L with L^2 - z^2 = (2 a sinh(x/(2 a)))^2
        L, w, x, z = 2.0, 1.0, 1.7, 1.0
        H, V = catenary.tensions(x, z, L, w, 1e12)
        self.assertGreater(V, w * L)  # the anchor end is lifted
        a = H / w
        self.assertAlmostEqual(math.sqrt(L * L - z * z), 2 * a * math.sinh(x / (2 * a)),
                               delta=1e-9)

    def test_moored_box_at_rest(self):
        # span 1.32497 m, fairlead 0.43337 m above the anchor: H 0.3338 N,
        # V 0.4297 N, fairlead tension 0.5441 N
        tension, H, V = catenary.line_tension((0, 0, 0.43337), (1.32497, 0, 0),
                                              1.455, 0.4927, 29.0)
        self.assertAlmostEqual(H, 0.3338, delta=1e-4)
        self.assertAlmostEqual(V, 0.4297, delta=1e-4)
        self.assertAlmostEqual(tension, math.hypot(H, V), delta=1e-15)


if __name__ == "__main__":
    unittest.main()

"""foamfmi.sectioninputs: which inputs a kept run changed, and the
sensitivity of a result to one from two runs."""

import unittest

from foamfmi import sectioninputs


class SectionInputsTest(unittest.TestCase):
    def test_changed(self):
        # A run kept before the inputs were options has the model's
        self.assertEqual(sectioninputs.changed({"period": 1.238}), [])
        self.assertEqual(sectioninputs.changed({"mass": 46.2207, "guideFriction": 0}), [])
        self.assertEqual(sectioninputs.changed({"mass": 46.8}), ["mass"])
        self.assertEqual(sectioninputs.changed({"KG": 0.108, "guideFriction": 0.5}),
                         ["guideFriction", "KG"])

    def test_sensitivity(self):
        base = ({"mass": 46.2207}, {"heave": 1.5})
        variant = ({"mass": 46.8}, {"heave": 1.4})
        s = sectioninputs.sensitivity(base, variant, "mass", "heave")
        self.assertAlmostEqual(s, -0.1 / (46.8 - 46.2207), places=12)

    def test_pick_variant_and_uncertainty(self):
        base = ({}, {})
        runs = [({"guideFriction": 0.2}, {}), ({"guideFriction": 0.5}, {})]
        self.assertIs(sectioninputs.pick_variant(base, runs, "guideFriction"), runs[1])
        self.assertIsNone(sectioninputs.pick_variant(base, [], "guideFriction"))
        friction = sectioninputs.INPUTS[0]
        self.assertAlmostEqual(sectioninputs.standard_uncertainty(friction), 0.25 / 3 ** 0.5,
                               places=12)


if __name__ == "__main__":
    unittest.main()

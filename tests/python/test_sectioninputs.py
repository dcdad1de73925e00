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

    def test_incident_scale(self):
        # A run whose generator's height is scaled changes the incident
        # amplitude, listed after the section's inputs
        self.assertEqual(sectioninputs.changed({"incidentScale": 1.0}), [])
        self.assertEqual(sectioninputs.changed({"incidentScale": 1.22, "mass": 46.8}),
                         ["mass", "incidentScale"])
        base = ({}, {"sway": 0.50, "incidentAmplitude": 0.0100})
        runs = [({"incidentScale": 1.1}, {}), ({"incidentScale": 0.7}, {})]
        self.assertIs(sectioninputs.pick_variant(base, runs, sectioninputs.INCIDENT), runs[1])
        # s per metre of the runs' own incident amplitudes: -0.02/0.002 =
        # -10 /m; u uniform over 10.7-12.0 mm: 0.65e-3/sqrt 3
        variant = ({"incidentScale": 1.2}, {"sway": 0.48, "incidentAmplitude": 0.0120})
        c = sectioninputs.incident_contribution(base, variant, "sway", 0.0120, 0.0107)
        self.assertAlmostEqual(c, -10.0 * 0.65e-3 / 3 ** 0.5, places=12)
        # the range is the same whichever end is the CFD's
        self.assertAlmostEqual(
            sectioninputs.incident_contribution(base, variant, "sway", 0.0107, 0.0120), c, places=15)

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

    def test_data_uncertainty(self):
        # One repetition: the calibration and the window only. RAO 2 per
        # a = 0.01 calibrated to 0.0002 (before and after): u_cal = 2 x
        # 0.0001/0.01 = 0.02; the window's 1.7-2.3: u_win = 0.3/sqrt 3
        case = {"roll": 2.0, "rollSpread": 0.0, "nRep": 1, "amplitude": 0.01,
                "amplitudeSpread": 0.0002, "rollWindowLow": 1.7, "rollWindowHigh": 2.3}
        u, parts = sectioninputs.data_uncertainty(case, "roll", "rollSpread")
        self.assertIsNone(parts["repetitions"])
        self.assertAlmostEqual(parts["calibration"], 0.02, places=12)
        self.assertAlmostEqual(parts["window"], 0.3 / 3 ** 0.5, places=12)
        self.assertAlmostEqual(u, (0.02 ** 2 + 0.03) ** 0.5, places=12)
        # Two repetitions 0.1 apart add half their spread; the springs'
        # mean takes the mean of the two gauges' windows; the drift load
        # (not per a, no window) has none
        case.update(nRep=2, rollSpread=0.1)
        self.assertAlmostEqual(
            sectioninputs.data_uncertainty(case, "roll", "rollSpread")[1]["repetitions"], 0.05)
        springs = {"tensionMean": 10.0, "amplitude": 0.01, "amplitudeSpread": 0.0,
                   "tensionWeatherWindowLow": 9.0, "tensionWeatherWindowHigh": 11.0,
                   "tensionLeeWindowLow": 8.0, "tensionLeeWindowHigh": 12.0}
        self.assertEqual(sectioninputs.window_range(springs, "tensionMean"), (8.5, 11.5))
        self.assertEqual(sectioninputs.data_uncertainty({"drift": 0.3}, "drift", None),
                         (0.0, {"repetitions": None, "calibration": None, "window": None}))


if __name__ == "__main__":
    unittest.main()

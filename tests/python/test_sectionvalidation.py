"""foamfmi.sectionvalidation: a run's flume switches (Allrun's, as
sectionwaves.read_case carries them from log.runSettings into run.dat) in
words, and the settings two runs must share to be set side by side."""

import unittest

from foamfmi import sectionvalidation as sv

# A kept run's settings (results/F0.5_H0.024_T1.158/run.dat's)
BASE = {"period": 1.158, "height": 0.024, "meshFactor": 0.5, "xIn": -7.0}
# The README's setting within 3 %, as read_key_values reads run.dat
SETTING = {"cellsPerHeight": 12.0, "cellsPerWavelength": 60.0, "ddt": "CrankNicolson_0.9",
           "momentumScheme": "Gauss_linearUpwindV_grad(U)"}


class Flume(unittest.TestCase):
    def test_default_flume(self):
        self.assertEqual(sv.flume(BASE), {})
        self.assertEqual(sv.flume_label(BASE), "the case's")

    def test_switches_in_words(self):
        run = dict(BASE, **SETTING)
        self.assertEqual(sv.flume(run), SETTING)
        self.assertEqual(sv.flume_label(run),
                         "12 cells a wave height, 60 cells a wavelength, CrankNicolson 0.9, "
                         "Gauss linearUpwindV grad(U)")
        self.assertEqual(sv.flume_label(dict(BASE, stepsPerPeriod=200.0, inletAbsorption="no")),
                         "T/200, inlet absorption no")

    def test_same_settings(self):
        run = dict(BASE, **SETTING)
        # another OpenFOAM, the same flume: the same settings
        self.assertTrue(sv.same_settings(BASE, dict(BASE, openfoam="v2312")))
        # another flume: only when the flume may differ
        self.assertFalse(sv.same_settings(BASE, run))
        self.assertTrue(sv.same_settings(BASE, run, same_flume=False))
        # another wave: never
        self.assertFalse(sv.same_settings(dict(BASE, period=1.238), run, same_flume=False))


if __name__ == "__main__":
    unittest.main()

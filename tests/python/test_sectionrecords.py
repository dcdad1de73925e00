"""foamfmi.sectionrecords: the flume experiment's records read and fitted,
and the errors that name the file and what was expected."""

import math
import os
import tempfile
import unittest

import numpy as np

from foamfmi import sectionrecords
from foamfmi.sectionrecords import RecordError


def write_record(path, t, columns):
    """A record as the experiment's CSV files are: an unnamed index column,
    then the columns with their units in brackets."""
    names = list(columns)
    with open(path, "w") as f:
        f.write(",Time [s]," + ",".join("%s [m]" % n for n in names) + "\n")
        for i, ti in enumerate(t):
            f.write("%d,%.6f," % (i, ti) + ",".join("%.9g" % columns[n][i] for n in names)
                    + "\n")


class SectionRecordsTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def test_window_and_wave_of_a_calibrated_run(self):
        # Period index 6 (T = 1.158 s): the wavemaker at rest for 2 s, then
        # a 5-period ramp up, steady, and a 5-period ramp down; WP_4 a
        # 12 mm wave. The window's fit gives that amplitude within 1e-6 m
        # (a pure sine over whole periods: round-off and the ramp's tail
        # are all that is left) and the wavemaker's period within 1e-4
        T = sectionrecords.WAVES[6][0]
        t = np.arange(0.0, 60.0, 0.005)
        moving = t - 2.0
        ramp = np.clip(moving / (5 * T), 0.0, 1.0) * np.clip((56.0 - t) / (5 * T), 0.0, 1.0)
        wm = np.where(moving > 0, 0.05 * ramp * np.sin(2 * math.pi * moving / T), 0.0)
        wave = 0.012 * np.sin(2 * math.pi * t / T)
        path = os.path.join(self.dir.name, "1061.csv")
        write_record(path, t, {"WM_Position": wm, "WP_4": wave})
        c = sectionrecords.analyse_calibration_run(path, 6)
        self.assertAlmostEqual(c["a"], 0.012, delta=1e-6)
        self.assertAlmostEqual(c["window"]["fWM"] * T, 1.0, delta=1e-4)
        self.assertGreaterEqual(c["window"]["periods"], 1)

    def test_errors_name_the_file_and_what_was_expected(self):
        t = np.arange(0.0, 10.0, 0.005)
        path = os.path.join(self.dir.name, "1061.csv")
        write_record(path, t, {"WM_Position": 0 * t})
        with self.assertRaisesRegex(RecordError, r"1061\.csv: no column WP_4"):
            sectionrecords.read_csv(path, ["WM_Position", "WP_4"])
        write_record(path, t, {"WM_Position": 0 * t, "WP_4": 0 * t})
        with self.assertRaisesRegex(RecordError, r"1061\.csv: WM_Position does not start from rest"):
            sectionrecords.analyse_calibration_run(path, 6)
        with open(os.path.join(self.dir.name, "SOURCE"), "w") as f:
            f.write("no origin\n")
        with self.assertRaisesRegex(RecordError, r"SOURCE.*'Repository: URL'"):
            sectionrecords.read_source(self.dir.name)


if __name__ == "__main__":
    unittest.main()

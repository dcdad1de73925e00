"""foamfmi.postprocessing: probes with a restart, the elevation of a gauge
line of equal and of graded cells, tables with a line cut short, tables
of whole rows only."""
import os
import shutil
import tempfile
import unittest

from foamfmi import postprocessing


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


PROBES = """# Probe 0 (1 0.5 0.45)
# Probe 1 (1 0.5 0.55)
# Probe 2 (2 0.5 0.45)
# Probe 3 (2 0.5 0.55)
#       Probe             0             1             2             3
#        Time
"""


class Probes(unittest.TestCase):
    def setUp(self):
        self.case = tempfile.mkdtemp(prefix="foamfmi.postprocessing.")
        base = os.path.join(self.case, "postProcessing", "waveGauges")
        write(os.path.join(base, "0", "alpha.water"),
              PROBES + "0.1 1 0 1 0.2\n0.2 1 0.5 1 0.4\n0.3 1 0.25 1")
        # the restart at 0.2 s repeats that time
        write(os.path.join(base, "0.2", "alpha.water"),
              PROBES + "0.2 1 0.9 1 0.9\n0.3 1 0.3 1 0.6\n")

    def tearDown(self):
        shutil.rmtree(self.case)

    def test_times_rows_points(self):
        base = os.path.join(self.case, "postProcessing", "waveGauges")
        points, times, rows = postprocessing.read_probes(base, "alpha.water")
        self.assertEqual(points[3], (2.0, 0.5, 0.55))
        self.assertEqual(times, [0.1, 0.2, 0.3])  # the cut line, then the restart's
        self.assertEqual(rows[1], [1.0, 0.5, 1.0, 0.4])
        self.assertEqual(rows[2], [1.0, 0.3, 1.0, 0.6])

    def test_elevation_of_equal_cells(self):
        # cells 0.4-0.5 and 0.5-0.6 m: eta = 0.4 + 0.1 (1 + alpha_2) - 0.5
        times, eta = postprocessing.read_gauges(self.case, 0.5)
        self.assertEqual(sorted(eta), [1.0, 2.0])
        for got, want in zip(eta[1.0], [0.0, 0.05, 0.03]):
            self.assertAlmostEqual(got, want, delta=1e-15)
        for got, want in zip(eta[2.0], [0.02, 0.04, 0.06]):
            self.assertAlmostEqual(got, want, delta=1e-15)

    def test_elevation_of_graded_cells(self):
        # centres 0.45 and 0.55 m from a lowest face at 0.42 m: cells
        # 0.42-0.48 and 0.48-0.62 m
        rows = [[1.0, 0.5]]
        eta, outside = postprocessing.elevation(rows, [(0.45, 0), (0.55, 1)], 0.5, bottom=0.42)
        self.assertAlmostEqual(eta[0], 0.42 + 0.06 + 0.14 * 0.5 - 0.5, delta=1e-15)
        self.assertEqual(outside, 1)  # the highest point is not air
        with self.assertRaises(postprocessing.PostProcessingError):
            postprocessing.elevation(rows, [(0.45, 0), (0.55, 1)], 0.5, bottom=0.5)

    def test_missing(self):
        with self.assertRaisesRegex(postprocessing.PostProcessingError, "system/lineGauges"):
            postprocessing.read_gauges(self.case, 0.5, name="lineGauges")


class Tables(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="foamfmi.postprocessing.")
        self.path = os.path.join(self.folder, "spring.dat")
        write(self.path, "# fmuConnector spring\n# Time length tension\n"
                         "0.01 0.2 0\n0.02 0.21 1.0\n0.03 0.2")

    def tearDown(self):
        shutil.rmtree(self.folder)

    def test_read_table_leaves_out_a_cut_line(self):
        self.assertEqual(postprocessing.read_table(self.path), [[0.01, 0.2, 0.0], [0.02, 0.21, 1.0]])
        # A table a run writes, cut inside its last number, keeps the row's
        # count of numbers but not its newline: left out all the same
        write(self.path, "# Time length tension\n0.01 0.2 0\n0.02 0.21 1.5")
        self.assertEqual(postprocessing.read_named_table(self.path)[1], [[0.01, 0.2, 0.0]])
        # A digitised curve that ends without a newline keeps its last row
        self.assertEqual(postprocessing.read_table(self.path), [[0.01, 0.2, 0.0], [0.02, 0.21, 1.5]])

    def test_named_columns(self):
        self.assertEqual(postprocessing.header_column(self.path, "tension"), 2)
        self.assertEqual(postprocessing.read_columns(self.path, ["tension"]),
                         [[0.01, 0.0], [0.02, 1.0]])
        names, rows = postprocessing.read_named_table(self.path)
        self.assertEqual(names, ["Time", "length", "tension"])
        self.assertEqual(len(rows), 2)
        with self.assertRaisesRegex(postprocessing.PostProcessingError, "no column force"):
            postprocessing.read_columns(self.path, ["force"])

    def test_whole_rows(self):
        # The file of setUp ends in a cut row (no newline): refused
        with self.assertRaisesRegex(postprocessing.PostProcessingError, "ends in a cut row"):
            postprocessing.whole_rows(self.path)
        # Or, asked to, counts the whole rows before it ("0.02 0.21 1.0\n": 14 bytes)
        self.assertEqual(postprocessing.whole_rows(self.path, cut_end=True), (2, 14))
        # Whole rows: counted, the longest with its newline ("0.02 0.21 1.0\n": 14 bytes)
        write(self.path, "# Time length tension\n0.01 0.2 0\n0.02 0.21 1.0\n")
        self.assertEqual(postprocessing.whole_rows(self.path), (2, 14))
        # A row of other columns than the header: refused, named
        write(self.path, "# Time length tension\n0.01 0.2 0\n0.02 0.21\n")
        with self.assertRaisesRegex(postprocessing.PostProcessingError, "row 2 has 2 columns"):
            postprocessing.whole_rows(self.path)

    def test_solver_log(self):
        log = os.path.join(self.folder, "log.interFoam")
        write(log, "Time = 0.01\nExecutionTime = 0.5 s  ClockTime = 1 s\nTime = 0.02\n"
                   "ExecutionTime = 0.9 s  ClockTime = 2 s\n"
                   "Rigid-body solver implicitNewmark: 6 solves, 20 Newton iterations,"
                   " 31 evaluations\n")
        self.assertEqual(postprocessing.solver_log(log),
                         {"timeSteps": 2, "executionTime": 0.9, "implicitNewmark": (6, 20, 31)})


if __name__ == "__main__":
    unittest.main()

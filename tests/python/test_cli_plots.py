"""foamfmi.cli: an analysis' command line and its errors; foamfmi.plots:
the window's shading, a response figure through gnuplot."""
import contextlib
import io
import os
import shutil
import tempfile
import unittest

from foamfmi import cli, plots


class CommandLine(unittest.TestCase):
    def test_options_reach_the_analysis(self):
        calls = []
        cli.run("prog", "prog [-no-plot] [-window T0 T1] [CASE]",
                lambda case, plot, window: calls.append((case, plot, window)),
                ["-no-plot", "-window", "6", "26", "caseDir"], window=True)
        cli.run("prog", "doc", lambda case, plot: calls.append((case, plot)), [])
        self.assertEqual(calls, [("caseDir", False, [6.0, 26.0]), (".", True)])

    def test_an_error_is_one_line_naming_the_program(self):
        def analyse(case, plot):
            raise ValueError("no waveHeight in constant/waveProperties")
        with self.assertRaises(SystemExit) as exit:
            cli.run("waveAnalysis", "doc", analyse, ["case"])
        self.assertEqual(str(exit.exception.code),
                         "waveAnalysis: no waveHeight in constant/waveProperties")

    def test_help_prints_the_docstring(self):
        out = io.StringIO()
        with contextlib.redirect_stdout(out), self.assertRaises(SystemExit):
            cli.run("prog", "prog: what it does.", lambda case, plot: None, ["-help"])
        self.assertIn("prog: what it does.", out.getvalue())
        self.assertIn("-no-plot", out.getvalue())


class Plots(unittest.TestCase):
    def test_shade(self):
        self.assertEqual(plots.shade(6, 26),
                         "set object 1 rect from 6, graph 0 to 26, graph 1 behind "
                         "fc rgb '#e8e8e8' fs solid 1.0 noborder")

    @unittest.skipIf(shutil.which("gnuplot") is None, "no gnuplot")
    def test_body_response_and_a_failing_script(self):
        folder = tempfile.mkdtemp(prefix="foamfmi.plots.")
        try:
            with open(os.path.join(folder, "elevation.dat"), "w") as f:
                f.write("# time eta(x=-1.5) eta(x=1.5)\n0 0 0\n1 0.01 -0.01\n2 0 0\n")
            motion = os.path.join(folder, "body.dat")
            with open(motion, "w") as f:
                for t in range(3):
                    f.write("%d %s\n" % (t, " ".join("%g" % (0.1 + 0.01 * t)
                                                      for _ in range(16))))
            plots.body_response(folder, "response", "a body", [-1.5, 1.5], 0.04, (0.5, 2),
                                motion, 0.1, 0.1, "tension (N)", {"line1": (motion, 7)})
            with open(os.path.join(folder, "response.png"), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
            with self.assertRaisesRegex(plots.PlotError, "gnuplot failed on .*bad.gp"):
                with contextlib.redirect_stderr(io.StringIO()):
                    plots.gnuplot(os.path.join(folder, "bad.gp"), ["plot nothing_at_all("])
        finally:
            shutil.rmtree(folder)


if __name__ == "__main__":
    unittest.main()

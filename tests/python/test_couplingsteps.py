"""foamfmi.couplingsteps: the steps of a real solver log of
tutorials/freeBoxWaves (OpenFOAM v1912, the added-mass coupling's first
two steps: data/addedMassCoupling.log), of a floatStepper log laid out as
floatStepper.C and pisoAddedMass.C print it (data/floatStepper.log), and
the equilibrium residual against accelerations built to satisfy, or to
miss by a known amount, Newton's law."""

import math
import os
import tempfile
import unittest

import numpy as np

from foamfmi import couplingsteps as cs

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


def read(name):
    with open(os.path.join(DATA, name)) as f:
        return f.read()


class AddedMassLog(unittest.TestCase):
    def setUp(self):
        self.steps = cs.steps_from_log(read("addedMassCoupling.log"))

    def test_steps(self):
        # two "Time =" lines; the trailing deltaT starts no step
        self.assertEqual([s["time"] for s in self.steps], [0.0012, 0.00264])
        self.assertEqual([s["deltaT"] for s in self.steps], [0.0012, 0.00144])
        # the tutorial's 3 outer correctors, no probe solves
        self.assertEqual([s["flowSolves"] for s in self.steps], [3, 3])
        self.assertEqual([s["probeSolves"] for s in self.steps], [0, 0])
        self.assertIsNone(self.steps[0]["acceleration"])

    def test_residuals(self):
        # every corrector's, as printed, in order
        self.assertEqual(self.steps[0]["residuals"],
                         [0.992655567159, 0.959196078928, 0.945894376964])
        self.assertEqual(cs.last_residuals(self.steps),
                         [(0.0012, 0.945894376964), (0.00264, 0.370042523914)])


class FloatStepperLog(unittest.TestCase):
    def setUp(self):
        self.steps = cs.steps_from_log(read("floatStepper.log"))

    def test_steps(self):
        self.assertEqual([s["time"] for s in self.steps], [0.5, 0.502])
        # 3 probe solves (surge, heave, pitch) and 2 PIMPLE loops (the zero
        # acceleration's and the step's); then the added mass kept
        self.assertEqual([s["flowSolves"] for s in self.steps], [5, 2])
        self.assertEqual([s["probeSolves"] for s in self.steps], [3, 0])
        self.assertEqual(self.steps[0]["residuals"], [])

    def test_state(self):
        s = self.steps[1]
        self.assertEqual(s["acceleration"], [0.12, 0.0, -0.18])
        self.assertEqual(s["angularAcceleration"], [0.0, -0.45, 0.0])
        self.assertEqual(s["centreOfMass"], [2.0102, 0.0, 0.40204])


class EquilibriumResidual(unittest.TestCase):
    mass, inertia, g = 12.0, (0.2, 0.151, 0.25), (0.0, 0.0, -9.81)
    cofr = (2.0, 0.0, 0.4)

    def forces_for(self, step, miss=(0.0, 0.0, 0.0), miss_angular=(0.0, 0.0, 0.0)):
        """Force and moment about CofR whose accelerations are the step's
        plus miss (linear) and miss_angular."""
        a = np.array(step["acceleration"]) + miss
        alpha = np.array(step["angularAcceleration"]) + miss_angular
        force = self.mass * (a - np.array(self.g))
        moment_cm = np.array(self.inertia) * alpha
        arm = np.array(step["centreOfMass"]) - np.array(self.cofr)
        return (list(force), list(moment_cm + np.cross(arm, force)))

    def test_zero_and_known_miss(self):
        steps = cs.steps_from_log(read("floatStepper.log"))
        d, dw = np.array([0.01, 0.0, -0.02]), np.array([0.0, 0.05, 0.0])
        forces = {0.5: self.forces_for(steps[0]),
                  0.502: self.forces_for(steps[1], d, dw)}
        got = dict(cs.equilibrium_residuals(steps, forces, self.mass, self.inertia,
                                            self.g, self.cofr))
        # Newton's law met: round-off of the moment's arm only
        self.assertLess(got[0.5], 1e-14)
        rho = math.sqrt(sum(self.inertia) / (3 * self.mass))
        a, alpha = np.array(steps[1]["acceleration"]), np.array(steps[1]["angularAcceleration"])
        expected = (math.sqrt(np.sum((rho * dw) ** 2) + np.sum(d ** 2))
                    / (math.sqrt(np.sum((rho * alpha) ** 2) + np.sum(a ** 2)) + 0.0981))
        self.assertAlmostEqual(got[0.502], expected, delta=1e-12)

    def test_unmatched_times_left_out(self):
        steps = cs.steps_from_log(read("floatStepper.log"))
        forces = {0.5005: self.forces_for(steps[0])}
        self.assertEqual(cs.equilibrium_residuals(steps, forces, self.mass, self.inertia,
                                                  self.g, self.cofr), [])


class Files(unittest.TestCase):
    def test_read_forces(self):
        with tempfile.TemporaryDirectory() as case:
            for start, rows in (("0", [(0.002, 1.0), (0.004, 2.0)]), ("0.004", [(0.004, 3.0)])):
                folder = os.path.join(case, "postProcessing", "boxForces", start)
                os.makedirs(folder)
                for kind, scale in (("force", 1.0), ("moment", 10.0)):
                    with open(os.path.join(folder, kind + ".dat"), "w") as f:
                        f.write("# %s\n# CofR : (2 0 0.4)\n#\n# Time total_x total_y total_z "
                                "pressure_x pressure_y pressure_z viscous_x viscous_y "
                                "viscous_z\n" % kind.capitalize())
                        for t, v in rows:
                            # v2012's plain columns; brackets as older writers
                            f.write("%g\t(%g 0 %g)\t(0 0 0)\t(0 0 0)\n" % (t, v * scale, -v)
                                    if start == "0" else
                                    "%g\t%g\t0\t%g\t0\t0\t0\t0\t0\t0\n" % (t, v * scale, -v))
            rows = cs.read_forces(case, "boxForces")
        self.assertEqual(sorted(rows), [0.002, 0.004])
        # the restart's row wins
        self.assertEqual(rows[0.004], ([3.0, 0.0, -3.0], [30.0, 0.0, -3.0]))
        self.assertEqual(rows[0.002], ([1.0, 0.0, -1.0], [10.0, 0.0, -1.0]))

    def test_missing_forces_named(self):
        with tempfile.TemporaryDirectory() as case:
            with self.assertRaisesRegex(cs.CouplingStepsError, "boxForces"):
                cs.read_forces(case, "boxForces")

    def test_summary_and_table(self):
        steps = cs.steps_from_log(read("addedMassCoupling.log"))
        residuals = cs.last_residuals(steps)
        s = cs.summary(steps, residuals)
        self.assertEqual(s["flowSolvesPerStep"], 3.0)
        self.assertAlmostEqual(s["residualMedian"], (0.945894376964 + 0.370042523914) / 2)
        self.assertEqual(s["residualMax"], 0.945894376964)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "steps.dat")
            cs.write_steps(path, steps, residuals[:1])
            times, solves, res = cs.read_steps(path)
        self.assertEqual(list(times), [0.0012, 0.00264])
        self.assertEqual(list(solves), [3, 3])
        self.assertAlmostEqual(res[0], 0.945894376964, places=6)
        self.assertTrue(math.isnan(res[1]))


if __name__ == "__main__":
    unittest.main()

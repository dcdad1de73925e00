"""foamfmi.foamdict and foamfmi.connectorscene on the tutorials' connector
cases: the restraints found through #include and $macros, their kinds and
attachment points, the points placed by a body's motion, the shapes."""
import math
import os
import shutil
import tempfile
import unittest

from foamfmi import connectorscene, foamdict
from foamfmi.dictionary import DictionaryError

TOP = os.environ.get("FOAMFMI_DIR") or os.path.join(os.path.dirname(__file__), "..", "..")
TUTORIALS = os.path.join(TOP, "tutorials")


def case(name):
    return os.path.join(TUTORIALS, name)


class Dictionaries(unittest.TestCase):
    def test_macros_and_include(self):
        # hingedPontoonsWaves: restraints `$hinge;` and
        # `parameters { $hingeParameters; }`, the solver's #include
        d = foamdict.parse(os.path.join(case("hingedPontoonsWaves"), "constant/dynamicMeshDict"))
        coeffs = d["addedMassRigidBodyMotionCoeffs"]
        hinge = coeffs["restraints"]["hinge3"]
        self.assertEqual(foamdict.word(hinge["fmu"]), "<constant>/fmu/hinge.fmu")
        self.assertEqual(foamdict.word(hinge["body"]), "pontoon3")
        self.assertEqual(foamdict.vector(hinge["parameters"]["B.p"]), [-0.325, 0, 0])
        self.assertIn("solver", coeffs)          # from rigidBodyMotionSolver
        self.assertEqual(foamdict.vector(coeffs["bodies"]["pontoon5"]["transform"])[9:],
                         [4.85, 0.5, 0.5])

    def test_sixdof_include(self):
        # coupledFloatingObjectsSixDoF: #include "<constant>/springConnector"
        d = foamdict.parse(os.path.join(case("coupledFloatingObjectsSixDoF"),
                                        "0.orig/pointDisplacement"))
        spring = d["boundaryField"]["floatingObject2"]["restraints"]["spring"]
        self.assertEqual(foamdict.word(spring["sixDoFRigidBodyMotionRestraint"]),
                         "fmuConnector")
        self.assertEqual(foamdict.vector(spring["parameters"]["A.p"]), [0.1, 0, 0.17])

    def test_value_macro_and_errors(self):
        folder = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, folder)
        path = os.path.join(folder, "d")
        with open(path, "w") as f:
            f.write("x 0.5; sub { p (1 $x 2); q $:sub.p; } bad $nothing;\n")
        with self.assertRaises(DictionaryError):
            foamdict.parse(path)
        with open(path, "w") as f:
            f.write("x 0.5; sub { p (1 $x 2); q $:sub.p; }\n")
        d = foamdict.parse(path)
        self.assertEqual(foamdict.vector(d["sub"]["p"]), [1, 0.5, 2])
        self.assertEqual(foamdict.vector(d["sub"]["q"]), [1, 0.5, 2])


class Connectors(unittest.TestCase):
    def test_kinds(self):
        for name, kind, a, b in (
                ("coupledFloatingObjects", "spring", [0.1, 0, 0.17], [-0.1, 0, 0.17]),
                ("damperFloatingObjects", "damper", [0.1, 0, 0.17], [-0.1, 0, 0.17]),
                ("hingedFloatingObjects", "hinge", [0.2, 0, 0.17], [-0.2, 0, 0.17]),
                ("coupledFloatingObjectsSixDoF", "spring", [0.1, 0, 0.17], [-0.1, 0, 0.17])):
            found, placements = connectorscene.read_connectors(case(name))
            self.assertEqual([(c.kind, c.body_a, c.body_b, c.p_a, c.p_b) for c in found],
                             [(kind, "floatingObject1", "floatingObject2", a, b)], name)
            self.assertEqual(placements["floatingObject1"][0], [-0.2, 0.5, 0.43], name)

    def test_start_positions(self):
        # hingedPontoonsWaves at t = 0: the hinge points of each pair meet
        # in the gap; the lines end at their anchors (no bodyB)
        found, placements = connectorscene.read_connectors(case("hingedPontoonsWaves"))
        motion = connectorscene.BodyMotion(case("hingedPontoonsWaves"), placements)
        by_name = {c.name: c for c in found}
        P, Q, axis = connectorscene.positions(by_name["hinge1"], motion, 0.0)
        self.assertEqual(by_name["hinge1"].kind, "hinge")
        for p, q, e in zip(P, Q, [2.575, 0.5, 0.5]):
            self.assertAlmostEqual(p, e)
            self.assertAlmostEqual(q, e)
        self.assertEqual(axis, [0, 1, 0])
        line = by_name["line1"]
        self.assertEqual(line.kind, "line")
        self.assertIsNone(line.body_b)
        self.assertEqual(connectorscene.positions(line, motion, 0.0)[1], [0.7643976, 0.5, 0])
        # No motion written: unknown after the start
        self.assertIsNone(connectorscene.positions(line, motion, 1.0))

    def test_motion(self):
        # A body turned by 90 deg about z and moved: P = c + R A.p
        folder = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, folder)
        # The case's dictionaries, not what a run of the tutorial left there
        shutil.copytree(case("coupledFloatingObjects"), os.path.join(folder, "c"),
                        ignore=shutil.ignore_patterns("postProcessing", "processor*",
                                                      "log.*", "plots", "VTK"))
        rbm = os.path.join(folder, "c/postProcessing/rigidBodyMotion")
        os.makedirs(rbm)
        for body, row in (("floatingObject1", "1 0 0 0 90 0 0 90"),
                          ("floatingObject2", "1 1 0 0 0 0 0 0")):
            with open(os.path.join(rbm, body + ".dat"), "w") as f:
                f.write("# Time CofR.x ...\n0.5 %s\n%s\n" % (row.split(" ", 1)[1], row))
        found, placements = connectorscene.read_connectors(os.path.join(folder, "c"))
        motion = connectorscene.BodyMotion(os.path.join(folder, "c"), placements)
        P, Q, _ = connectorscene.positions(found[0], motion, 1.0)
        for got, expected in zip(P + Q, [0, 0.1, 0.17, 0.9, 0, 0.17]):
            self.assertAlmostEqual(got, expected)
        self.assertIsNone(connectorscene.positions(found[0], motion, 2.0))


class Shapes(unittest.TestCase):
    def test_coil(self):
        P, Q = [0, 0, 0], [1, 0, 0]
        points = connectorscene.coil(P, Q, 0.05, turns=5)
        self.assertEqual(points[0], P)
        self.assertEqual(points[-1], Q)
        for p in points:
            self.assertLessEqual(math.hypot(p[1], p[2]), 0.05 + 1e-12)
        flat = connectorscene.coil(P, Q, 0.05, flat_normal=[0, 1, 0])
        self.assertTrue(all(abs(p[1]) < 1e-12 for p in flat))
        self.assertAlmostEqual(max(abs(p[2]) for p in flat), 0.05)

    def test_damper_and_hinge(self):
        cylinder, rod = connectorscene.damper([0, 0, 0], [1, 0, 0])
        self.assertEqual(cylinder[0], [0, 0, 0])
        self.assertEqual(rod[1], [1, 0, 0])
        self.assertGreater(cylinder[1][0], rod[0][0])     # the rod enters it
        ends = connectorscene.hinge([1, 0, 0], [1, 0, 0.002], [0, 2, 0], 0.1)
        self.assertEqual(ends, [[1, -0.05, 0.001], [1, 0.05, 0.001]])


if __name__ == "__main__":
    unittest.main()

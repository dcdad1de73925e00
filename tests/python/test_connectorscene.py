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

    def written_case(self, tutorial):
        """A copy of the tutorial's dictionaries, no run's output."""
        folder = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, folder)
        shutil.copytree(case(tutorial), os.path.join(folder, "c"),
                        ignore=shutil.ignore_patterns("postProcessing", "processor*", "log.*",
                                                      "plots", "VTK", "[1-9]*", "0.[0-9]*"))
        return os.path.join(folder, "c")

    def test_sixdof_written_state(self):
        # No table of the motion: the sixDoF patches' state that OpenFOAM
        # writes into <time>/pointDisplacement places the spring's ends.
        # floatingObject1 turned by 90 deg about z (orientation body to
        # global) and moved to (0 0 1): P = c + R A.p, A.p = (0.1 0 0.17)
        c = self.written_case("coupledFloatingObjectsSixDoF")
        os.makedirs(os.path.join(c, "1"))
        patch = ("    %s\n    {\n        type sixDoFRigidBodyDisplacement;\n"
                 "        centreOfMass %s;\n        mass 1;\n"
                 "        momentOfInertia (1 1 1);\n        centreOfRotation %s;\n"
                 "        orientation %s;\n        value uniform (0 0 0);\n    }\n")
        with open(os.path.join(c, "1", "pointDisplacement"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class pointVectorField;"
                    " object pointDisplacement; }\ndimensions [0 1 0 0 0 0 0];\n"
                    "internalField uniform (0 0 0);\nboundaryField\n{\n"
                    + patch % ("floatingObject1", "(0 0 1)", "(0 0 1)", "(0 -1 0 1 0 0 0 0 1)")
                    + patch % ("floatingObject2", "(1 0 0)", "(1 0 0)", "(1 0 0 0 1 0 0 0 1)")
                    + "}\n")
        trees = connectorscene.read_dictionaries(c)
        found, placements = connectorscene.read_connectors(c, trees)
        motion = connectorscene.BodyMotion(c, placements, trees["constant/dynamicMeshDict"])
        self.assertTrue(motion.has_motion("floatingObject1", [1.0]))
        P, Q, _ = connectorscene.positions(found[0], motion, 1.0)
        for got, expected in zip(P + Q, [0, 0.1, 1.17, 0.9, 0, 0.17]):
            self.assertAlmostEqual(got, expected)
        # A time with no state written: unknown
        self.assertFalse(motion.has_motion("floatingObject1", [2.0]))
        self.assertIsNone(connectorscene.positions(found[0], motion, 2.0))

    def test_sixdof_solver_state(self):
        # A sixDoFRigidBodyMotion solver (its body the first of its patches):
        # placed at the start at its centre of rotation, later by
        # <time>/uniform/sixDoFRigidBodyMotionState
        c = self.written_case("coupledFloatingObjects")
        with open(os.path.join(c, "constant", "dynamicMeshDict"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                    " object dynamicMeshDict; }\n"
                    "dynamicFvMesh dynamicMotionSolverFvMesh;\n"
                    "motionSolverLibs (sixDoFRigidBodyMotion);\n"
                    "motionSolver sixDoFRigidBodyMotion;\n"
                    "sixDoFRigidBodyMotionCoeffs\n{\n    patches (box);\n"
                    "    innerDistance 0.1;\n    outerDistance 0.3;\n    mass 2;\n"
                    "    centreOfMass (0.5 0.5 0.5);\n    momentOfInertia (1 1 1);\n"
                    "    restraints\n    {\n        spring\n        {\n"
                    "            sixDoFRigidBodyMotionRestraint fmuConnector;\n"
                    "            fmu \"<constant>/fmu/linearSpring.fmu\";\n"
                    "            body box;\n"
                    "            parameters { A.p (0.1 0 0); B.p (2 0 0); }\n"
                    "        }\n    }\n}\n")
        os.makedirs(os.path.join(c, "1", "uniform"))
        with open(os.path.join(c, "1", "uniform", "sixDoFRigidBodyMotionState"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                    " object sixDoFRigidBodyMotionState; }\n"
                    "centreOfRotation (1 1 1);\norientation (0 -1 0 1 0 0 0 0 1);\n"
                    "velocity (0 0 0);\n")
        trees = connectorscene.read_dictionaries(c)
        found, placements = connectorscene.read_connectors(c, trees)
        motion = connectorscene.BodyMotion(c, placements, trees["constant/dynamicMeshDict"])
        self.assertEqual([(x.name, x.body_a, x.body_b) for x in found], [("spring", "box", None)])
        for time, expected in ((0.0, [0.6, 0.5, 0.5]), (1.0, [1, 1.1, 1])):
            P, Q, _ = connectorscene.positions(found[0], motion, time)
            for got, e in zip(P + Q, expected + [2, 0, 0]):
                self.assertAlmostEqual(got, e)


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

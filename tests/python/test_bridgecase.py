"""foamfmi.bridgecase's rigidBodyMotion dictionaries, read back by
foamfmi.foamdict; foamfmi.cli's scratch folder."""
import os
import tempfile
import unittest

from foamfmi import cli, foamdict
from foamfmi.bridgecase import entries, fmu_restraint, linear_spring, rigid_body, rigid_body_model


def parsed(text):
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "dynamicMeshDict")
        with open(path, "w") as f:
            f.write(text)
        return foamdict.parse(path)


class Entries(unittest.TestCase):
    def test_values(self):
        self.assertEqual(entries({"a": 0.1, "n": 3, "v": (1, 0, 2), "w": "on", "skip": None}, 4),
                         "    a 0.1;\n    n 3;\n    v (1.0 0.0 2.0);\n    w on;\n")

    def test_model_reads_back(self):
        model = rigid_body_model(
            rigid_body("hull", 2, 0.1, (0, 0, 0), "floating"),
            linear_spring("spring", "hull", (0, 0, 1), (0, 0, 0), 50.0, 0, 0.5)
            + fmu_restraint("line", "/x/catenary.fmu", "hull", {"EA": 1e5, "A.p": (0, 0, 0)},
                            "buoy", report="off"),
            "Newmark", g=(0, 0, -9.81), extra="    qDot (0 1);\n")
        d = parsed(model)
        self.assertEqual(d["solver"]["type"], ["Newmark"])
        self.assertEqual(foamdict.vector(d["g"]), [0.0, 0.0, -9.81])
        self.assertEqual(list(d["restraints"]), ["spring", "line"])
        spring, line = d["restraints"]["spring"], d["restraints"]["line"]
        self.assertEqual(spring["stiffness"], ["50.0"])
        self.assertEqual(line["bodyB"], ["buoy"])
        self.assertEqual(line["fmu"], ['"/x/catenary.fmu"'])
        self.assertEqual(line["parameters"]["EA"], ["100000.0"])
        self.assertEqual(line["report"], ["off"])
        self.assertIn("hull", d["bodies"])

    def test_parameters_as_text_and_no_gravity(self):
        d = parsed(rigid_body_model("", fmu_restraint("s", "/s.fmu", "hull", "stiffness 1;"), g=None))
        self.assertNotIn("g", d)
        self.assertEqual(d["restraints"]["s"]["parameters"]["stiffness"], ["1"])


class Scratch(unittest.TestCase):
    def test_removed_unless_kept(self):
        with self.assertRaises(SystemExit):
            with cli.scratch("scratchTest.", False) as work:
                self.assertTrue(os.path.isdir(work))
                raise SystemExit(1)
        self.assertFalse(os.path.exists(work))
        with cli.scratch("scratchTest.", True) as work:
            pass
        self.assertTrue(os.path.isdir(work))
        os.rmdir(work)


if __name__ == "__main__":
    unittest.main()

"""foamfmi.dictionary on the tutorials' own dictionaries, and entries set
in place."""
import os
import shutil
import tempfile
import unittest

from foamfmi import dictionary

TOP = os.environ.get("FOAMFMI_DIR") or os.path.join(os.path.dirname(__file__), "..", "..")
WAVE_TANK = os.path.join(TOP, "tutorials", "waveTank")


class Read(unittest.TestCase):
    def test_wave_properties(self):
        # tutorials/waveTank/constant/waveProperties: the inlet's Stokes II
        # waves, H = 0.05 m, T = 1.5 s, ramped over one period
        path = os.path.join(WAVE_TANK, "constant", "waveProperties")
        self.assertEqual(dictionary.read_scalar(path, "waveHeight"), 0.05)
        self.assertEqual(dictionary.read_scalar(path, "wavePeriod"), 1.5)
        self.assertEqual(dictionary.read_scalar(path, "rampTime"), 1.5)

    def test_gravity(self):
        path = os.path.join(WAVE_TANK, "constant", "g")
        self.assertEqual(dictionary.read_vector(path, "value"), [0.0, 0.0, -9.81])

    def test_application(self):
        path = os.path.join(WAVE_TANK, "system", "controlDict")
        self.assertEqual(dictionary.read_word(path, "application"), "interFoamAliasSafe")

    def test_missing_entry_names_key_and_file(self):
        path = os.path.join(WAVE_TANK, "constant", "g")
        with self.assertRaisesRegex(dictionary.DictionaryError, r"no waveHeight in .*constant/g"):
            dictionary.read_scalar(path, "waveHeight")

    def test_entry_text(self):
        path = os.path.join(WAVE_TANK, "constant", "g")
        text = dictionary.read_text(path)
        self.assertEqual(dictionary.entry_text(text, "value"), "( 0 0 -9.81 )")
        with self.assertRaises(dictionary.DictionaryError):
            dictionary.entry_text(text, "dimension")

    def test_comments_are_skipped(self):
        text = dictionary.strip_comments("a 1; // b 2;\n/* c 3;\n d 4; */ e 5;")
        self.assertNotIn("b 2", text)
        self.assertNotIn("d 4", text)
        self.assertIn("e 5;", text)

    def test_boundary(self):
        text = dictionary.strip_comments("""FoamFile { version 2.0; }
3
(
    inlet { type patch; nFaces 20; startFace 100; }
    front { type empty; inGroups 1(empty); nFaces 0; startFace 120; }
    floatingObject // the body
    { type wall; nFaces 12; startFace 120; }
)""")
        self.assertEqual(dictionary.boundary_patches(text),
                         [("inlet", "patch", 20), ("front", "empty", 0),
                          ("floatingObject", "wall", 12)])


class Points(unittest.TestCase):
    POINTS = ("/*--- banner ---*/\nFoamFile\n{\n    version 2.0;\n    format ascii;\n"
              "    class vectorField;\n    object points;\n}\n// * * * //\n\n\n"
              "3\n(\n(0 0 0)\n(1.25 -0.5 4e-3)\n(2 0.1 1)\n)\n")

    def write(self, text):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        path = os.path.join(d, "points")
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_points(self):
        path = self.write(self.POINTS)
        self.assertEqual(dictionary.read_points(path),
                         [(0.0, 0.0, 0.0), (1.25, -0.5, 0.004), (2.0, 0.1, 1.0)])

    def test_count_that_differs(self):
        path = self.write(self.POINTS.replace("3\n(", "4\n("))
        with self.assertRaisesRegex(dictionary.DictionaryError, "3 points read, the file says 4"):
            dictionary.read_points(path)

    def test_not_a_points_file(self):
        path = self.write("FoamFile { object points; }\nvalue (0 0 0);\n")
        with self.assertRaisesRegex(dictionary.DictionaryError, "no list of points"):
            dictionary.read_points(path)


class Write(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="foamfmi.dictionary.")
        self.path = os.path.join(self.folder, "controlDict")
        shutil.copy(os.path.join(WAVE_TANK, "system", "controlDict"), self.path)

    def tearDown(self):
        shutil.rmtree(self.folder)

    def test_set_entry(self):
        dictionary.set_entry(self.path, "endTime", 4.5, width=16)
        dictionary.set_entry(self.path, "writeInterval", 0.5)
        with open(self.path) as f:
            text = f.read()
        self.assertIn("\nendTime         4.5;\n", text)
        self.assertIn("\nwriteInterval 0.5;\n", text)
        self.assertEqual(dictionary.read_scalar(self.path, "endTime"), 4.5)

    def test_set_entry_that_is_not_there(self):
        with self.assertRaisesRegex(dictionary.DictionaryError, "0 entries noSuchEntry"):
            dictionary.set_entry(self.path, "noSuchEntry", 1)

    def test_substitute(self):
        dictionary.substitute(self.path, r"^(application\s+)\w+;", r"\g<1>interFoam;")
        self.assertEqual(dictionary.read_word(self.path, "application"), "interFoam")
        with self.assertRaises(dictionary.DictionaryError):
            dictionary.substitute(self.path, r"^noSuchEntry\s", "")


if __name__ == "__main__":
    unittest.main()

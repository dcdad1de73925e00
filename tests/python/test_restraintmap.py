"""foamfmi.restraintmap and foamfmi.dictspan: the converter's mapping of
built-in restraints (the sixDoF centre of rotation as OpenFOAM's
constructor makes it) and where an entry stands in a dictionary's text.
foamFmiConvert itself, with OpenFOAM's reader, is tested by
tests/bridge/test_convert.py."""
import os
import tempfile
import unittest
from unittest import mock

from foamfmi import convert as converter
from foamfmi.dictionary import DictionaryError
from foamfmi.dictspan import dictionary_spans, indentation
from foamfmi.restraintmap import centre_of_rotation, convert, sixdof_attachment

TEXT = """FoamFile { version 2.0; }
// a comment with a brace {
sixDoFRigidBodyMotionCoeffs
{
    mass            #eval{ $rho*$Lx };
    momentOfInertia #codeStream
    {
        code
        #{
            os << "{" ; // not a brace of the dictionary
        #};
    };
    /* restraints { fake { } } */
    restraints
    {
        #include "more"
        spring
        {
            sixDoFRigidBodyMotionRestraint linearSpring;
            anchor (0 0 1);
        }
    }
}
"""


def words(**entries):
    """A parsed dictionary: each value as its tokens."""
    return {k: v if isinstance(v, dict) else v.replace("(", "( ").replace(")", " )").split()
            for k, v in entries.items()}


class Spans(unittest.TestCase):
    def test_entry_spans(self):
        spans = dictionary_spans(TEXT, "dynamicMeshDict")
        start, end = spans[("sixDoFRigidBodyMotionCoeffs", "restraints", "spring")]
        self.assertTrue(TEXT[start:end].startswith("spring\n"))
        self.assertTrue(TEXT[start:end].endswith("anchor (0 0 1);\n        }"))
        self.assertEqual(indentation(TEXT, start), " " * 8)
        start, end = spans[("sixDoFRigidBodyMotionCoeffs", "mass")]
        self.assertEqual(TEXT[start:end], "mass            #eval{ $rho*$Lx };")
        self.assertIn(("sixDoFRigidBodyMotionCoeffs", "momentOfInertia"), spans)
        # a commented-out dictionary is no entry
        self.assertNotIn(("sixDoFRigidBodyMotionCoeffs", "restraints", "fake"), spans)

    def test_unbalanced(self):
        with self.assertRaisesRegex(DictionaryError, "dynamicMeshDict: entry a: no closing"):
            dictionary_spans("a { b { c 1; }", "dynamicMeshDict")


class CentreOfRotation(unittest.TestCase):
    def test_centre_of_mass_without_constraints(self):
        motion = words(centreOfMass="(0.5 0.45 0.35)")
        self.assertEqual(centre_of_rotation(motion, "m"), [0.5, 0.45, 0.35])

    def test_initial_centre_of_mass_first(self):
        motion = words(centreOfMass="(1 1 1)", initialCentreOfMass="(0.5 0.45 0.35)")
        self.assertEqual(centre_of_rotation(motion, "m"), [0.5, 0.45, 0.35])

    def test_line_constraint(self):
        # OpenFOAM's floatingObject (dynamicMeshDict.sixDoF): a line and an
        # axis constraint; the line's centreOfRotation is the centre
        motion = words(centreOfMass="(0.5 0.45 0.35)", constraints={
            "fixedLine": words(sixDoFRigidBodyMotionConstraint="line",
                               centreOfRotation="(0.5 0.45 0.1)", direction="(0 1 0)"),
            "fixedAxis": words(sixDoFRigidBodyMotionConstraint="axis", axis="(0 1 0)")})
        self.assertEqual(centre_of_rotation(motion, "m"), [0.5, 0.45, 0.1])

    def test_last_point_line_plane_wins_default_centre_of_mass(self):
        motion = words(centreOfMass="(1 2 3)", constraints={
            "p": words(sixDoFRigidBodyMotionConstraint="point", centreOfRotation="(0 0 0)"),
            "l": words(sixDoFRigidBodyMotionConstraint="plane", normal="(0 0 1)")})
        self.assertEqual(centre_of_rotation(motion, "m"), [1.0, 2.0, 3.0])

    def test_attachment_in_the_body_frame(self):
        # turned 90 deg about z: the global offset (0.1 0.2 0.3) from the
        # centre is (0.2 -0.1 0.3) in the body's frame
        motion = words(centreOfMass="(1 1 1)", orientation="(0 -1 0 1 0 0 0 0 1)")
        got = sixdof_attachment([1.1, 1.2, 1.3], motion, "m")
        for g, e in zip(got, [0.2, -0.1, 0.3]):
            self.assertAlmostEqual(g, e, places=14)  # 1 - 0.9 etc.: round-off 1e-16


class Mapping(unittest.TestCase):
    SPRING = words(anchor="(0.5 0 0.35)", refAttachmentPt="(0 -0.1 0.25)", stiffness="100",
                   damping="0", restLength="0.35")

    def test_rigid_spring_same_points(self):
        c = convert("linearSpring", self.SPRING, "rigidBody", {}, "d, restraint spring")
        self.assertEqual(c.fmu, "linearSpring")
        self.assertEqual(c.parameters, {"stiffness": "100", "damping": "0", "restLength": "0.35",
                                        "A.p": "(0 -0.1 0.25)", "B.p": "(0.5 0 0.35)"})

    def test_sixdof_spring_from_the_centre_of_rotation(self):
        # The README's sixDoF spring: refAttachmentPt (0.5 0.35 0.35),
        # centre of rotation (0.5 0.45 0.1) from the line constraint
        spring = dict(self.SPRING, refAttachmentPt="( 0.5 0.35 0.35 )".split())
        motion = words(centreOfMass="(0.5 0.45 0.35)", constraints={
            "fixedLine": words(sixDoFRigidBodyMotionConstraint="line",
                               centreOfRotation="(0.5 0.45 0.1)")})
        c = convert("linearSpring", spring, "sixDoF", motion, "d")
        self.assertEqual(c.parameters["A.p"], "(0 -0.1 0.25)")

    def test_damper(self):
        c = convert("linearDamper", words(coeff="5"), "rigidBody", {}, "d")
        self.assertEqual((c.fmu, c.parameters["damping"], c.parameters["A.p"], c.notes),
                         ("translationalDamper", "5", "(0 0 0)", []))
        c = convert("linearDamper", words(coeff="5"), "sixDoF", words(centreOfMass="(0 0 0)"), "d")
        self.assertEqual(len(c.notes), 1)

    def test_angular_damper(self):
        c = convert("sphericalAngularDamper", words(coeff="0.5"), "sixDoF",
                    words(centreOfMass="(0 0 0)"), "d")
        self.assertEqual((c.fmu, c.parameters["damping"], c.notes), ("rotationalDamper", "0.5", []))

    def test_axial_angular_spring(self):
        spring = words(axis="(0 1 0)", stiffness="2", damping="0.1")
        c = convert("linearAxialAngularSpring", spring, "sixDoF", words(centreOfMass="(0 0 0)"),
                    "d")
        self.assertEqual((c.fmu, c.parameters["B.axis"], c.parameters["referenceOrientation"]),
                         ("axialAngularSpring", "(0 1 0)", "(1 0 0 0 1 0 0 0 1)"))
        # the rigidBodyMotion one turns bodies away from their reference
        self.assertIsNone(convert("linearAxialAngularSpring", spring, "rigidBody", {}, "d"))

    def test_tabulated_axial_angular_spring(self):
        with tempfile.TemporaryDirectory() as case:
            os.makedirs(os.path.join(case, "constant"))
            with open(os.path.join(case, "constant", "table"), "w") as f:
                f.write("// angle moment\n3\n(\n    (-90 4)\n    (0 0) (90 -4.5)\n)\n")
            spring = words(axis="(0 1 0)", damping="0.1", angleFormat="degrees",
                           outOfBounds="repeat")
            spring["file"] = ['"$FOAM_CASE/constant/table"']
            c = convert("tabulatedAxialAngularSpring", spring, "sixDoF",
                        words(centreOfMass="(0 0 0)"), "d", case=case)
            self.assertEqual((c.fmu, c.parameters["B.axis"], c.parameters["table.points"],
                              c.parameters["angleInDegrees"], c.parameters["outOfBounds"],
                              c.notes),
                             ("tabulatedAxialAngularSpring", "(0 1 0)", "3", "1", "3", []))
            # 64 values each, the unused points 0
            self.assertEqual(c.parameters["table.angle"],
                             "(-90 0 90" + " 0" * 61 + ")")
            self.assertEqual(c.parameters["table.moment"],
                             "(4 0 -4.5" + " 0" * 61 + ")")
            # outOfBounds warn (the default) is clamp without the warning
            del spring["outOfBounds"]
            c = convert("tabulatedAxialAngularSpring", spring, "sixDoF", {}, "d", case=case)
            self.assertEqual(c.parameters["outOfBounds"], "1")
            self.assertIn("without the warning", c.notes[0])
            spring["file"] = ['"<constant>/missing"']
            with self.assertRaisesRegex(DictionaryError, "^d: table file .*missing: "):
                convert("tabulatedAxialAngularSpring", spring, "sixDoF", {}, "d", case=case)

    def test_spherical_angular_spring(self):
        spring = words(referenceOrientation="(0 -1 0 1 0 0 0 0 1)", stiffness="2",
                       damping="0.1")
        c = convert("sphericalAngularSpring", spring, "sixDoF", words(centreOfMass="(0 0 0)"),
                    "d")
        self.assertEqual((c.fmu, c.parameters["stiffness"], c.parameters["damping"],
                          c.parameters["referenceOrientation"], c.notes),
                         ("sphericalAngularSpring", "2", "0.1", "(0 -1 0 1 0 0 0 0 1)", []))
        c = convert("sphericalAngularSpring", words(stiffness="2", damping="0"), "sixDoF",
                    words(centreOfMass="(0 0 0)"), "d")
        self.assertEqual(c.parameters["referenceOrientation"], "(1 0 0 0 1 0 0 0 1)")

    def test_left_out(self):
        self.assertIsNone(convert("prescribedRotation", {}, "rigidBody", {}, "d"))

    def test_errors_name_the_entry(self):
        spring = {k: v for k, v in self.SPRING.items() if k != "stiffness"}
        with self.assertRaisesRegex(DictionaryError,
                                    "^constant/dynamicMeshDict, restraint spring: no entry "
                                    "stiffness"):
            convert("linearSpring", spring, "rigidBody", {},
                    "constant/dynamicMeshDict, restraint spring")
        spring = dict(self.SPRING, anchor="( 0.5 0 )".split())
        with self.assertRaisesRegex(DictionaryError, r"entry anchor is \( 0.5 0 \), expected 3 "
                                    r"numbers in \( \)"):
            convert("linearSpring", spring, "rigidBody", {}, "d")


class OpenFoamFrame(unittest.TestCase):
    MOTION = words(centreOfMass="(0.5 0.45 0.35)", constraints={
        "fixedLine": words(sixDoFRigidBodyMotionConstraint="line",
                           centreOfRotation="(0.5 0.45 0.1)")})

    def test_openfoam_frame_used_when_it_agrees(self):
        frame = ([0.5, 0.45, 0.1], [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
        with mock.patch.object(converter, "openfoam_frame", return_value=frame):
            centre, _, source = converter.motion_frame(self.MOTION, "m")
        self.assertEqual(centre, [0.5, 0.45, 0.1])
        self.assertIn("as OpenFOAM's sixDoFRigidBodyMotion gives it", source)

    def test_disagreement_stops_the_conversion(self):
        frame = ([0.5, 0.45, 0.35], [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
        with mock.patch.object(converter, "openfoam_frame", return_value=frame):
            with self.assertRaisesRegex(converter.ConvertError,
                                        r"^m: OpenFOAM gives the motion the centre of rotation "
                                        r"\[0.5, 0.45, 0.35\].*convert by hand"):
                converter.motion_frame(self.MOTION, "m")

    def test_state_in_the_dictionary_uses_the_rules(self):
        motion = dict(self.MOTION, centreOfRotation="( 9 9 9 )".split())
        with mock.patch.object(converter, "openfoam_frame") as asked:
            centre, _, source = converter.motion_frame(motion, "m")
        asked.assert_not_called()
        self.assertEqual(centre, [0.5, 0.45, 0.1])
        self.assertIn("the dictionary holds a motion state", source)


if __name__ == "__main__":
    unittest.main()

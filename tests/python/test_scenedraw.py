"""foamfmi.scenedraw.section_pieces: a line's polyline cut into its
sections where the points' sections change, at the joints when known."""
import unittest

from foamfmi.scenedraw import SECTION, LINE, section_colour, section_pieces

# 11 points from the fairlead (0, 0, 0) down to the anchor (10, 0, -10)
POINTS = [[float(i), 0.0, -float(i)] for i in range(11)]


class SectionPieces(unittest.TestCase):
    def test_uniform_line_is_one_piece(self):
        pieces = section_pieces(POINTS, [0] * 11)
        self.assertEqual(pieces, [(0, POINTS)])

    def test_joint_unknown_cuts_the_segment_in_the_middle(self):
        # Points 1-5 in the rope (1), 6-11 in the chain (0): the joint lies
        # between (4, 0, -4) and (5, 0, -5)
        pieces = section_pieces(POINTS, [1] * 5 + [0] * 6)
        self.assertEqual([k for k, _ in pieces], [1, 0])
        self.assertEqual(pieces[0][1], POINTS[:5] + [[4.5, 0.0, -4.5]])
        self.assertEqual(pieces[1][1], [[4.5, 0.0, -4.5]] + POINTS[5:])

    def test_joint_known_is_the_cut(self):
        joint = (4.2, 0.5, -4.7)
        pieces = section_pieces(POINTS, [1] * 5 + [0] * 6, [joint])
        self.assertEqual(pieces[0][1][-1], list(joint))
        self.assertEqual(pieces[1][1][0], list(joint))

    def test_a_section_between_two_points(self):
        # Section 1 (0-based) shorter than a step: both joints on the
        # segment from the last point of section 2 to the first of section 0,
        # joint 2 (sections 1, 2) nearer the fairlead, at thirds without joints
        pieces = section_pieces(POINTS, [2] * 3 + [0] * 8)
        self.assertEqual([k for k, _ in pieces], [2, 1, 0])
        for (_, a), (_, b) in zip(pieces, pieces[1:]):
            self.assertEqual(a[-1], b[0])
        self.assertAlmostEqual(pieces[1][1][0][0], 2 + 1 / 3, places=12)
        self.assertAlmostEqual(pieces[1][1][1][0], 2 + 2 / 3, places=12)
        joints = [(2.8, 0, -2.8), (2.1, 0, -2.1)]
        pieces = section_pieces(POINTS, [2] * 3 + [0] * 8, joints)
        self.assertEqual(pieces[1][1], [list(joints[1]), list(joints[0])])

    def test_colours(self):
        # The anchor's section keeps the colour of a uniform line
        self.assertEqual(section_colour(0), LINE)
        self.assertEqual(len(set(SECTION)), len(SECTION))
        self.assertEqual(section_colour(len(SECTION)), SECTION[0])


if __name__ == "__main__":
    unittest.main()

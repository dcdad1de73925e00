"""foamfmi.readmeblock: the block between two markers replaced, the rest
of the page kept byte for byte; -check compares without writing."""
import os
import tempfile
import unittest

from foamfmi import readmeblock

BEGIN, END = "<!-- t: begin -->", "<!-- t: end -->"
PAGE = "# Title\n\nBefore.\n\n%s\nold row\n%s\n\nAfter.\n" % (BEGIN, END)


class Block(unittest.TestCase):
    def setUp(self):
        fd, self.path = tempfile.mkstemp(suffix=".md")
        with os.fdopen(fd, "w") as f:
            f.write(PAGE)

    def tearDown(self):
        os.remove(self.path)

    def read(self):
        with open(self.path) as f:
            return f.read()

    def test_replaced_and_the_rest_kept(self):
        readmeblock.write(self.path, BEGIN, END, ["| a |", "| 1 |"])
        self.assertEqual(self.read(), PAGE.replace("old row", "| a |\n| 1 |"))

    def test_check_passes_on_the_same_block(self):
        readmeblock.write(self.path, BEGIN, END, ["old row"], check=True)
        self.assertEqual(self.read(), PAGE)

    def test_check_fails_on_another_block_and_writes_nothing(self):
        with self.assertRaisesRegex(readmeblock.ReadmeBlockError, "run ./report"):
            readmeblock.write(self.path, BEGIN, END, ["new row"], True, "./report")
        self.assertEqual(self.read(), PAGE)

    def test_no_markers(self):
        with self.assertRaisesRegex(readmeblock.ReadmeBlockError, "no markers"):
            readmeblock.write(self.path, "<!-- x: begin -->", END, [])
        self.assertEqual(self.read(), PAGE)


if __name__ == "__main__":
    unittest.main()

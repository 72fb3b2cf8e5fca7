#!/usr/bin/env python3
"""scripts/check-rooms.py on a small house of two rooms: it passes as built, and fails, naming the
file and line, on a source file its room's README does not list, on a listed file that is not
there, on an arm's PerArm place cast by hand, and on an include that climbs a room."""
import pathlib
import subprocess
import sys
import tempfile
import unittest

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "check-rooms.py"
TABLE = "| file | job |\n|---|---|\n"


class CheckRooms(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.root = pathlib.Path(self.dir.name)
        self.write("README.md", "# A small house\n")
        self.write("common/README.md",
                   f"# common\n\n{TABLE}| `thing.hpp` | a thing |\n\nMay include: nothing\n")
        self.write("common/include/common/thing.hpp", "#pragma once\n// A thing.\n")
        self.write("common/src/thing.cpp", '#include "common/thing.hpp"\n')
        self.write("twin/README.md",
                   f"# twin\n\n{TABLE}| `user.hpp` | uses the thing |\n\nMay include: common\n")
        self.write("twin/include/twin/user.hpp",
                   '#pragma once\n#include "common/thing.hpp"\n// Uses the thing.\n')

    def tearDown(self):
        self.dir.cleanup()

    def write(self, relative, text):
        path = self.root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)

    def check(self):
        run = subprocess.run([sys.executable, str(SCRIPT), "--root", str(self.root)],
                             capture_output=True, text=True)
        return run.returncode, run.stdout

    def assert_fails_with(self, line):
        code, out = self.check()
        self.assertEqual(code, 1, out)
        self.assertIn(line, out)

    def test_the_house_as_built_passes(self):
        code, out = self.check()
        self.assertEqual(code, 0, out)
        self.assertIn("every include goes down", out)

    def test_a_source_file_its_readme_does_not_list_fails(self):
        self.write("twin/src/helper.cpp", '#include "twin/user.hpp"\n')
        self.assert_fails_with("twin/src/helper.cpp: not listed in twin/README.md")

    def test_a_listed_file_that_is_not_there_fails(self):
        self.write("twin/README.md", f"# twin\n\n{TABLE}| `user.hpp`, `gone.hpp` | two |\n\n"
                                     "May include: common\n")
        self.assert_fails_with("twin/README.md: lists `gone.hpp`, which is not in the room")

    def test_an_arms_place_cast_by_hand_fails(self):
        self.write("twin/include/twin/user.hpp",
                   '#pragma once\n#include "common/thing.hpp"\n'
                   "auto& x = things[static_cast<std::size_t>(" + "raven::index(arm))];\n")
        self.assert_fails_with("twin/include/twin/user.hpp:3: an arm's place cast by hand")

    def test_the_other_arms_place_counted_by_hand_fails(self):
        self.write("twin/include/twin/user.hpp",
                   '#pragma once\n#include "common/thing.hpp"\n'
                   "auto& y = things[1 - " + "slot(arm)];\n")
        self.assert_fails_with("twin/include/twin/user.hpp:3: an arm's place cast by hand")

    def test_an_include_that_climbs_fails(self):
        self.write("common/include/common/thing.hpp", '#pragma once\n#include "twin/user.hpp"\n')
        self.assert_fails_with('common/include/common/thing.hpp:2: common includes "twin/user.hpp"')


if __name__ == "__main__":
    unittest.main()

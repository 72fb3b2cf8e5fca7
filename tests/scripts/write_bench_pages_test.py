#!/usr/bin/env python3
"""scripts/write-bench-pages.py: a run's rows replace their sections' rows, sections left out of
the run keep theirs under the line of the run that measured them (one line for a day and a
machine), the README shows the rows with a target, writing twice changes nothing, and a page without markers is refused by name."""
import json
import pathlib
import subprocess
import sys
import tempfile
import unittest

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "write-bench-pages.py"
HEADER = "| section | measurement | value | target | note |\n|---|---|---|---|---|\n"
OLD_CAPTION = "Measured 2026-01-01 on Old CPU, 2 cores, Linux 1, GCC 1, Release build."
OLD_ROWS = ("| loop | free-running | 100 steps/s | >= 50 steps/s (met) | old |\n"
            "| training | rings placed | 95.0 % | >= 80 % (met) | old |\n"
            "| training | behaviour cloning | 563 s |  | old |\n")


def page(block):
    return f"# Page\n\n<!-- {{m}}:begin -->\n{block}<!-- {{m}}:end -->\n\nAfter.\n"


class WriteBenchPages(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.root = pathlib.Path(self.dir.name)
        (self.root / "docs").mkdir()
        old = f"{OLD_CAPTION}\n\n{HEADER}{OLD_ROWS}"
        (self.root / "docs/benchmarks.md").write_text(page(old).format(m="bench"))
        (self.root / "README.md").write_text(page(old).format(m="bench-headline"))
        machine = {"date": "2026-11-28", "cpu": "New CPU", "cores": 2, "kernel": "Linux 2",
                   "compiler": "GCC 2"}
        (self.root / "results.json").write_text(json.dumps({"machine": machine}))
        (self.root / "results.md").write_text(
            HEADER + "| loop | free-running | 200 steps/s | >= 50 steps/s (met) | new |\n"
                     "| replay | 2arm | 101 x real time | >= 100 x real time (met) | new |\n")

    def tearDown(self):
        self.dir.cleanup()

    def write(self):
        return subprocess.run([sys.executable, str(SCRIPT), str(self.root),
                               str(self.root / "results.json"), str(self.root / "results.md")],
                              capture_output=True, text=True)

    def test_sections_not_run_keep_their_rows_under_their_own_line(self):
        self.assertEqual(self.write().returncode, 0)
        docs = (self.root / "docs/benchmarks.md").read_text()
        self.assertIn("Measured 2026-11-28 on New CPU", docs)
        self.assertIn("| loop | free-running | 200 steps/s", docs)
        self.assertNotIn("| loop | free-running | 100 steps/s", docs)
        self.assertIn("| replay | 2arm | 101 x", docs)
        kept = docs.index(OLD_CAPTION + " Sections not in the run above:")
        self.assertGreater(docs.index("| training | rings placed | 95.0 %"), kept)
        self.assertGreater(docs.index("| training | behaviour cloning"), kept)
        self.assertGreater(kept, docs.index("| replay | 2arm"))
        self.assertTrue(docs.endswith("<!-- bench:end -->\n\nAfter.\n"))

    def test_the_readme_shows_the_rows_with_a_target(self):
        self.write()
        readme = (self.root / "README.md").read_text()
        self.assertIn("| training | rings placed | 95.0 %", readme)
        self.assertNotIn("behaviour cloning", readme)
        self.assertIn("| replay | 2arm | 101 x", readme)

    def test_writing_the_same_run_twice_changes_nothing(self):
        self.write()
        first = (self.root / "docs/benchmarks.md").read_text(), (self.root / "README.md").read_text()
        self.write()
        second = (self.root / "docs/benchmarks.md").read_text(), (self.root / "README.md").read_text()
        self.assertEqual(first, second)
        self.assertEqual(first[0].count("Sections not in the run above"), 1)

    def test_rows_of_the_same_day_and_machine_share_its_line(self):
        self.write()
        (self.root / "results.md").write_text(
            HEADER + "| controller | jitter p99 | 0.1 ms | < 0.2 ms (met) | new |\n")
        self.assertEqual(self.write().returncode, 0)
        for name in ("docs/benchmarks.md", "README.md"):
            text = (self.root / name).read_text()
            self.assertEqual(text.count("2026-11-28 on New CPU"), 1, name)
            self.assertIn("| controller | jitter p99 | 0.1 ms", text)
            self.assertIn("| replay | 2arm | 101 x", text)
            self.assertLess(text.index("| controller | jitter"), text.index("| replay | 2arm"))
            self.assertIn(OLD_CAPTION.replace("Measured ", "", 1), text)  # the older line stays

    def test_a_page_without_markers_is_named(self):
        (self.root / "README.md").write_text("# no markers\n")
        docs = (self.root / "docs/benchmarks.md").read_text()
        result = self.write()
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("README.md has no <!-- bench-headline:begin -->", result.stderr)
        self.assertEqual((self.root / "docs/benchmarks.md").read_text(), docs)  # nothing half-written


if __name__ == "__main__":
    unittest.main()

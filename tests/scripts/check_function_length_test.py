#!/usr/bin/env python3
"""scripts/check-function-length.py on small files: a function's length runs from its signature
to its closing brace; namespaces, classes and control statements are not functions; lambdas,
braces in strings and comments stay inside the function they are in."""

import importlib.util
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "check-function-length.py"
spec = importlib.util.spec_from_file_location("check_function_length", SCRIPT)
check = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check)


def body(lines):
    return "".join(f"  x += {i};\n" for i in range(lines))


class FunctionLength(unittest.TestCase):
    def test_a_function_counts_from_its_signature_to_its_closing_brace(self):
        text = "namespace a {\nint f(int x)\n    const {\n" + body(5) + "}\n}  // namespace a\n"
        self.assertEqual(check.functions(text), [("f", 2, 8)])

    def test_class_members_count_and_the_class_does_not(self):
        text = ("struct S {\n  void g() {\n" + body(3) + "  }\n  int h;\n};\n"
                "S::S() : h(1) {\n}\n")
        self.assertEqual(check.functions(text), [("g", 2, 5), ("S::S", 9, 2)])

    def test_lambdas_braces_in_literals_and_control_statements_stay_inside(self):
        text = ("void f() {\n  auto l = [&] { return '{'; };  // }\n  if (x) {\n"
                "    s = \"}}\";\n  }\n  /* { */\n}\n")
        self.assertEqual(check.functions(text), [("f", 1, 7)])

    def test_a_long_function_fails_the_check_by_file_and_line(self):
        with tempfile.TemporaryDirectory() as root:
            (Path(root) / "room").mkdir()
            (Path(root) / "room" / "long.cpp").write_text("\nvoid f() {\n" + body(100) + "}\n")
            run = subprocess.run([sys.executable, str(SCRIPT), "--root", root],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 1)
            self.assertIn("room/long.cpp:2: f is 102 lines (at most 100)", run.stdout)
            (Path(root) / "room" / "long.cpp").write_text("void f() {\n" + body(98) + "}\n")
            run = subprocess.run([sys.executable, str(SCRIPT), "--root", root],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stdout)


if __name__ == "__main__":
    unittest.main()

"""Bad models never crash or hang: each error carries the model's line."""

import time
import unittest

from lpy_helpers import run_text


class Errors(unittest.TestCase):
    def test_python_syntax_error_at_its_line(self):
        r = run_text("x = 1\nAxiom: A\nderivation length: 1\nproduction:\nA :\n  if x >\n    produce B\nendlsystem\n")
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 6)
        self.assertIn("SyntaxError", r["error"]["message"])

    def test_unclosed_parameter_list_at_its_line(self):
        r = run_text("Axiom: A\nderivation length: 1\nproduction:\nA --> B(1\nendlsystem\n")
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 4)

    def test_rule_without_arrow_or_colon(self):
        r = run_text("Axiom: A\nderivation length: 1\nproduction:\n\nA B C\nendlsystem\n")
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 5)

    def test_exception_in_a_rule_body_at_the_bodys_line(self):
        src = "Axiom: A(0)\nderivation length: 2\nproduction:\nA(x) :\n  y = 1 / x\n  produce A(y)\nendlsystem\n"
        r = run_text(src)
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 5)
        self.assertIn("ZeroDivisionError", r["error"]["message"])

    def test_exception_in_a_function_the_body_calls(self):
        src = "def f(x):\n  return [][x]\nAxiom: A\nderivation length: 1\nproduction:\nA --> B(f(3))\nendlsystem\n"
        r = run_text(src)
        self.assertEqual(r["error"]["line"], 2)
        self.assertIn("IndexError", r["error"]["message"])

    def test_unknown_import_names_the_module(self):
        r = run_text("import numpy\nAxiom: F\nendlsystem\n")
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 1)
        self.assertIn("numpy", r["error"]["message"])

    def test_string_explosion_stops_at_max_modules(self):
        r = run_text("Axiom: A\nderivation length: 40\nproduction:\nA --> AA\nendlsystem\n", max_modules=10_000)
        self.assertFalse(r["ok"])
        self.assertIn("limit", r["error"]["message"])

    def test_endless_loop_in_a_body_stops_at_the_time_limit(self):
        src = "Axiom: A\nderivation length: 1\nproduction:\nA :\n  while True: pass\nendlsystem\n"
        t0 = time.monotonic()
        r = run_text(src, time_limit=1)
        self.assertLess(time.monotonic() - t0, 10)
        self.assertFalse(r["ok"])
        self.assertIn("time limit", r["error"]["message"])

    def test_endless_derivation_stops_at_the_time_limit(self):
        src = ("Axiom: A(0)\nderivation length: 10**9\nproduction:\nA(x) --> A(x+1)\nendlsystem\n")
        t0 = time.monotonic()
        r = run_text(src, time_limit=1)
        self.assertLess(time.monotonic() - t0, 10)
        self.assertIn("time limit", r["error"]["message"])

    def test_exit_in_the_model_is_an_error_not_our_exit(self):
        r = run_text("import sys\nAxiom: A\nderivation length: 1\nproduction:\nA :\n  sys.exit(3)\nendlsystem\n")
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 6)

    def test_missing_main_file(self):
        from lpy_helpers import run

        r = run({}, "absent.lpy", {})
        self.assertFalse(r["ok"])
        self.assertIn("absent.lpy", r["error"]["message"])

    def test_composed_file_missing(self):
        r = run_text("sub = Lsystem('nothere.lpy')\nAxiom: F\nendlsystem\n")
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 1)

    def test_result_is_json_serialisable_even_with_objects(self):
        import json

        r = run_text("Axiom: A(Vector3(1,2,3), 'a', True, [1, 2], NurbsCurve2D([(0,0,1),(1,0,1)], degree=1))\nendlsystem\n")
        self.assertTrue(r["ok"], r["error"])
        json.dumps(r)
        self.assertEqual(r["lstring"], "A(1.0,2.0,3.0,'a',1,1,2,@obj0)")


if __name__ == "__main__":
    unittest.main()

"""Whole L+C models: lpfg's derivation checked against hand counts of the course objects
(vlab `oofs/ext/12-LPFG`, GPL-3; their text is quoted here), contexts, groups, decomposition,
interpretation, and the error paths."""

import unittest

from lpfg_support import count, modules, run_lpfg

QUADRATIC_KOCH = """#include <lpfgall.h>
#define ANGLE 90
derivation length: 4;
Axiom: Right(90) F(1.0);
F(v) :
{
	produce F(v) Left(ANGLE) F(v) Right(ANGLE) F(v) Right(ANGLE) F(v)
		F(v) Left(ANGLE) F(v) Left(ANGLE)  F(v) Right(ANGLE) F(v);
}
"""

SNOWFLAKE = """#include <lpfgall.h>
#define ANGLE 60
derivation length: 4;
Axiom: Right(90) F(1.0);
F(v) :
{
	produce F(v) Left(ANGLE)
		F(v) Right(2*ANGLE) F(v)
		Left(ANGLE) F(v);
}
"""

COMPOUND_INTERP = """#include <lpfgall.h>
#define ANGLE 45
derivation length: 4;
module A(float);
module I(float);
Axiom: SetWidth(3) A(1.0);
A(v) :
{
	produce I(v)
		SB() Right(ANGLE) A(v) EB()
		SB() Left(ANGLE)  A(v) EB()
		I(v) A(v);
}
I(v) : { produce I(v) I(v); }
interpretation:
A(v) : { produce IncColor() F(v); }
I(v) : { produce F(v); }
"""

RECURSIVE = """#include <lpfgall.h>
#include <math.h>
#define WIDTH 	3
#define	T	8	// age of the structure
#define D	2	// delay in producing laterals
#define R	1.5	// growth rate
#define ANGLE	45	// branching angle
derivation length: 1;
module A(float);
module I(float);
module M(float);
Axiom: SetWidth(WIDTH) A(T);
interpretation:
maximum depth: 100;
A(t) :
{
	if(t<D)
		produce IncColor() F(t);
	else
		produce M(t-D) A(t-1);
}
M(t) :
{
	float x = 0.5*pow(R, t);
	produce
		I(x)
		SB() Right(ANGLE) A(t) EB()
		SB() Left(ANGLE) A(t) EB()
		I(x);
}
I(x) : { produce F(x); }
"""

ACROPETAL_SIGNAL = """#include <lpfgall.h>
derivation length: 4;
module B(int);
ignore: Left F;
Axiom: B(1) F(1) Left(30) B(0) F(1) B(0);
B(a) < B(b) : { produce B(a); }
B(a) : { if (a == 1) produce B(a) F(2); }
"""


class CourseObjectTest(unittest.TestCase):
    def test_quadratic_koch_has_8_to_the_4_segments(self):  # 01-quadratic-Koch
        r = run_lpfg(QUADRATIC_KOCH)
        self.assertEqual(r["steps"], 4)
        self.assertEqual(count(r, "F"), 8 ** 4)
        # 6 turns per rewritten segment: 1 + 6·(1 + 8 + 64 + 512)
        self.assertEqual(count(r, "Left") + count(r, "Right"), 1 + 6 * 585)

    def test_snowflake_counts_its_turns(self):  # 03-snowflake
        r = run_lpfg(SNOWFLAKE)
        self.assertEqual(count(r, "F"), 256)
        self.assertEqual(count(r, "Left"), 170)  # L(n+1) = L(n) + 2·4^n
        self.assertEqual(count(r, "Right"), 86)  # R(n+1) = R(n) + 4^n, from the axiom's 1

    def test_compound_leaf_interpreted(self):  # 05-compound-interp
        r = run_lpfg(COMPOUND_INTERP)
        # a(n+1) = 3a(n), i(n+1) = 2i(n) + 2a(n): after 4 steps 81 apices and 130 internodes
        self.assertEqual(count(r, "IncColor"), 81)
        self.assertEqual(count(r, "F"), 81 + 130)
        self.assertEqual(count(r, "SB"), count(r, "EB"))
        self.assertEqual(count(r, "SB"), 2 * (1 + 3 + 9 + 27))

    def test_recursive_interpretation_to_its_maximum_depth(self):  # 10-recursive
        r = run_lpfg(RECURSIVE)
        # f(t) = 2 + 2 f(t-2) + f(t-1), f(0) = f(1) = 1: f(8) = 341 segments
        self.assertEqual(count(r, "F"), 341)
        lengths = sorted({float(a[0]) for n, a in modules(r) if n == "F"})
        self.assertIn(0.5 * 1.5 ** 6, lengths)

    def test_a_signal_moves_up_through_ignored_modules(self):  # as in 03-signal-down
        r = run_lpfg(ACROPETAL_SIGNAL)
        names = [n for n, _ in modules(r)]
        self.assertEqual(names.count("B"), 3)
        self.assertEqual(names.count("F"), 2 + 4)  # the first B adds F(2) each step
        b_values = [a[0] for n, a in modules(r) if n == "B"]
        self.assertEqual(b_values, ["1", "1", "1"])


class DerivationTest(unittest.TestCase):
    def test_a_body_without_produce_does_not_apply_and_the_next_rule_is_tried(self):
        src = """derivation length: 1;
module A(int);
Axiom: A(1) A(2);
A(x): { if (x == 2) produce F(20); }
A(x): { produce F(x); }
"""
        self.assertEqual(run_lpfg(src)["lstring"], "F(1.0)F(20.0)")

    def test_groups_switch_with_usegroup(self):
        src = """derivation length: 2;
int n = 0;
StartEach: { UseGroup(n % 2 == 0 ? 1 : 2); n++; }
Axiom: X;
group 1:
X(): { produce Y; }
group 2:
Y(): { produce F(1); }
endgroup
"""
        self.assertEqual(run_lpfg(src)["lstring"], "F(1.0)")

    def test_new_right_context_when_deriving_backward(self):
        src = """derivation length: 1;
module A(int);
Start: { Backward(); }
Axiom: A(0) A(0) A(5);
A(x) >> A(y): { produce A(y + 1); }
"""
        self.assertEqual(run_lpfg(src)["lstring"], "A(7)A(6)A(5)")

    def test_decomposition_runs_after_each_step(self):
        src = """derivation length: 1;
module A(); module B();
Axiom: A;
A(): { produce B; }
decomposition:
maximum depth: 3;
B(): { produce F(1) B; }
"""
        self.assertEqual(count(run_lpfg(src), "F"), 3)

    def test_function_files_are_read_by_name(self):
        fset = """funcgalleryver 1 1
items: 1
fver 1 1
name: rise
samples: 100
flip: off
points: 4
0 0
0.3333 0.3333
0.6667 0.6667
1 1
"""
        src = "derivation length: 0;\nAxiom: F(func(rise, 0.25));\n"
        r = run_lpfg(src, {"functions.fset": fset})
        self.assertAlmostEqual(float(modules(r)[0][1][0]), 0.25, places=3)


class ErrorTest(unittest.TestCase):
    def test_a_syntax_error_gives_its_line_and_column(self):
        r = run_lpfg("derivation length: 1;\nAxiom: A;\nA(): { produce F(1) }\n")
        self.assertFalse(r["ok"])
        self.assertEqual((r["error"]["line"], r["error"]["column"]), (3, 21))

    def test_an_endless_loop_stops_at_the_time_limit(self):
        src = "derivation length: 1;\nAxiom: A;\nA(): {\n int i = 0;\n while (1) { i++; }\n produce F(1);\n}\n"
        r = run_lpfg(src, time_limit=0.5)
        self.assertFalse(r["ok"])
        self.assertIn("time limit", r["error"]["message"])

    def test_a_string_explosion_stops_at_max_modules(self):
        src = "derivation length: 40;\nAxiom: F(1);\nF(x): { produce F(x) F(x); }\n"
        r = run_lpfg(src, max_modules=10000)
        self.assertFalse(r["ok"])
        self.assertIn("10000", r["error"]["message"])

    def test_an_unknown_name_is_reported_at_its_line(self):
        r = run_lpfg("derivation length: 1;\nAxiom: A;\nA(): {\n  produce F(nowhere(1));\n}\n")
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 4)
        self.assertIn("nowhere", r["error"]["message"])


if __name__ == "__main__":
    unittest.main()

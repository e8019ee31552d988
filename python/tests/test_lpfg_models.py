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

HORMONE_UP = """#include <lpfgall.h>
#define LENGTH 1
#define WIDTH 5
#define ANGLE 45.0
derivation length: 1;
module A();
module B();
module X();
ignore: Left Right;
Axiom: SetWidth(WIDTH) X();
X():
{
	produce
		B()
		SB() Right(ANGLE) A() EB() A()
		SB()  Left(ANGLE) A() EB() A()
		SB() Right(ANGLE) A() EB() A()
		SB()  Left(ANGLE) A() EB() A()
		SB() Right(ANGLE) A() EB() A();
}
B() < A():
{
	produce B();
}
interpretation:
A():
{
	produce SetColor(1) F(LENGTH);
}
B():
{
	produce SetColor(2) F(LENGTH);
}
"""

SIGNAL_DOWN = """#include <lpfgall.h>
#define LENGTH 1
#define WIDTH 5
#define ANGLE 45.0
derivation length: 1;
module A();
module B();
module X();
ignore: Left Right;
Axiom: SetWidth(WIDTH) X();
X():
{
	produce
		A() SB() Right(ANGLE) A() EB()
		A() SB()  Left(ANGLE) A() EB()
		A() SB() Right(ANGLE) A() EB()
		A() SB()  Left(ANGLE) A() EB()
		A() SB() Right(ANGLE) A() EB()
		B();
}
B():
{
	produce A();
}
A() > B():
{
	produce B();
}
interpretation:
A():
{
	produce SetColor(1) F(LENGTH);
}
B():
{
	produce SetColor(2) F(LENGTH);
}
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

    def test_an_acropetal_signal_climbs_a_node_and_its_branch_each_step(self):  # 01-hormone-up
        for steps, signalled in ((1, 1), (2, 3), (3, 5), (6, 11)):
            r = run_lpfg(HORMONE_UP, steps=steps)
            colours = [a[0] for n, a in modules(r) if n == "SetColor"]
            self.assertEqual(len(colours), 11)  # 11 segments, each with its colour
            self.assertEqual(colours.count("2"), signalled, steps)

    def test_a_basipetal_signal_goes_down_the_main_axis_only(self):  # 03-signal-down
        for steps, at in ((1, 10), (2, 8), (3, 6), (6, 0)):
            r = run_lpfg(SIGNAL_DOWN, steps=steps)
            colours = [a[0] for n, a in modules(r) if n == "SetColor"]
            self.assertEqual(colours.count("2"), 1, steps)
            self.assertEqual(colours.index("2"), at, steps)


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


class LpfgFeatureTest(unittest.TestCase):
    def test_in_new_right_context_walks_the_branches_in_a_while_loop(self):  # as InNewContext
        src = """derivation length: 1;
module N(float);
Start: { Backward(); }
Axiom: N(0) SB() N(2) EB() SB() N(3) EB() N(4);
N(a):
{
  float b, sum = 0;
  while (InNewRightContext(SB() N(b) EB())) sum += b;
  if (InNewRightContext(N(b))) sum += b;
  produce N(a + sum);
}
"""
        r = run_lpfg(src)
        self.assertEqual([a[0] for n, a in modules(r) if n == "N"], ["9.0", "2.0", "3.0", "4.0"])

    def test_a_constructor_with_initialisers_and_an_enum_in_a_struct(self):  # as UserMenu
        src = """derivation length: 0;
struct S { int c; enum { E0, E1 } e; S(void) : c(4), e(E1) {} };
module M(S);
Axiom: M(S());
interpretation:
M(s): { if (s.e == S::E1) produce F(s.c); }
"""
        self.assertEqual(run_lpfg(src)["lstring"], "F(4.0)")

    def test_the_first_view_is_drawn(self):  # as Multiview, LPFG-FibonacciFlorets
        src = """derivation length: 0;
Start: { UseView(Big); UseView(Small); }
Axiom: A B;
interpretation:
vgroup Big:
A(): { produce F(10); }
vgroup Small:
A(): { produce F(1); }
B(): { produce F(2); }
"""
        r = run_lpfg(src)
        self.assertEqual(r["lstring"], "F(10.0)B()")
        self.assertIn("Small", r["notes"][-1]["message"])

    def test_a_gillespie_group_rewrites_one_module_per_step(self):
        src = """derivation length: 5;
Start: { UseGroup(1); SeedGillespie(3); }
module A();
Axiom: A A A;
ggroup 1:
A(): { propensity 2.0 produce F(1) A; }
"""
        r = run_lpfg(src)
        self.assertEqual(count(r, "F"), 5)
        self.assertEqual(count(r, "A"), 3)
        self.assertEqual(run_lpfg(src)["lstring"], r["lstring"])  # the same seed, the same plant


class BetweenStepsTest(unittest.TestCase):
    def test_cut_removes_the_rest_of_its_branch_at_the_next_step(self):
        src = """derivation length: %d;
module X();
Axiom: F(1) SB() F(2) X() F(3) SB() F(4) EB() F(5) EB() F(6);
X(): { produce Cut(); }
"""
        self.assertIn("Cut()F(3.0)", run_lpfg(src % 1)["lstring"])  # produced, not yet applied
        self.assertEqual(run_lpfg(src % 2)["lstring"], "F(1.0)SB()F(2.0)EB()F(6.0)")

    def test_getpos_receives_the_turtles_position_through_interpretation(self):
        src = """derivation length: 1;
module A();
Axiom: F(2) Left(90) A() GetPos(0, 0, 0);
interpretation:
A(): { produce F(3); }
"""
        r = run_lpfg(src)
        pos = [a for n, a in modules(r) if n == "GetPos"][0]
        self.assertAlmostEqual(float(pos[0]), -3.0)
        self.assertAlmostEqual(float(pos[1]), 2.0)


class SeedTest(unittest.TestCase):
    SRC = "derivation length: 3;\nAxiom: A;\nmodule A();\nA(): { produce F(ran(1.0)) A; }\n"

    def test_the_same_seed_gives_the_same_plant_and_another_seed_another(self):
        a, b = run_lpfg(self.SRC, seed=1), run_lpfg(self.SRC, seed=1)
        self.assertEqual(a["lstring"], b["lstring"])
        self.assertNotEqual(a["lstring"], run_lpfg(self.SRC, seed=2)["lstring"])
        self.assertTrue(all(0 <= float(v[0]) < 1 for n, v in modules(a) if n == "F"))


class EnvironmentTest(unittest.TestCase):
    E_FILE = "executable: honda81 -e commfile.e density.spec\ncommunication type: files\n"
    SPEC = "verbose: off\nradius:  0.1\n3d case: on\n"

    def test_honda81_stops_the_weaker_of_two_queries_that_meet(self):
        src = "derivation length: 1;\nAxiom: E1(1) E1(0.5) F(5) E1(0.5) SB() Left(90) E1(0.5) EB();\n"
        r = run_lpfg(src, {"commfile.e": self.E_FILE, "density.spec": self.SPEC})
        self.assertEqual([a[0] for n, a in modules(r) if n == "E1"], ["1", "0", "0", "0"])
        self.assertEqual(r["notes"], [])

    def test_without_a_communication_file_queries_keep_their_values_with_a_note(self):
        r = run_lpfg("derivation length: 1;\nAxiom: E1(1) E1(0.5);\n")
        self.assertEqual([a[0] for n, a in modules(r) if n == "E1"], ["1.0", "0.5"])
        self.assertIn("environment", r["notes"][0]["message"])


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

    def test_a_loop_that_produces_without_end_stops_at_max_modules_at_its_line(self):
        src = "derivation length: 1;\nAxiom: A;\nmodule A();\nA(): {\n for (int i = 0; i < 100000000; i++) nproduce F(1);\n produce;\n}\n"
        r = run_lpfg(src, max_modules=1000)
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 5)

    def test_every_truncation_of_a_model_gives_a_result_or_an_error_at_a_line(self):
        for source in (COMPOUND_INTERP, RECURSIVE):
            for k in range(0, len(source), 5):
                r = run_lpfg(source[:k], time_limit=2)
                if not r["ok"]:
                    self.assertGreaterEqual(r["error"]["line"], 1, (k, r["error"]))

    def test_an_unknown_name_is_reported_at_its_line(self):
        r = run_lpfg("derivation length: 1;\nAxiom: A;\nA(): {\n  produce F(nowhere(1));\n}\n")
        self.assertFalse(r["ok"])
        self.assertEqual(r["error"]["line"], 4)
        self.assertIn("nowhere", r["error"]["message"])


if __name__ == "__main__":
    unittest.main()

"""C++ in L+C bodies: each statement kind, C's integer arithmetic, structs and vectors."""

import unittest

from lpfg_support import axiom_of, run_lpfg, values


def result_of(body, declarations=""):
    return values(axiom_of(body, declarations))[0]


class StatementTest(unittest.TestCase):
    def test_integer_division_truncates_towards_zero_and_remainder_keeps_the_sign(self):
        self.assertEqual(result_of("result = 7/2;"), 3.0)
        self.assertEqual(result_of("result = -7/2;"), -3.0)
        self.assertEqual(result_of("result = 7.0/2;"), 3.5)
        self.assertEqual(result_of("result = -7%3;"), -1.0)
        self.assertEqual(result_of("int i = 7; float f = i; result = f/2;"), 3.5)
        self.assertEqual(result_of("int i = 3.9; result = i;"), 3.0)
        self.assertEqual(result_of("result = (int) 2.7 + (float) 1/2;"), 2.5)

    def test_float_is_single_precision_and_double_is_not(self):
        # 0.1 added ten times: C's float gives 1.0000001192092896, double 0.9999999999999999
        self.assertEqual(result_of("float f = 0; for (int i = 0; i < 10; i++) f += 0.1; result = f;"), 1.0000001192092896)
        body = "double d = 0; for (int i = 0; i < 10; i++) d += 0.1; result = d < 1 ? 1 : 2;"
        self.assertEqual(result_of(body), 1.0)

    def test_module_parameters_declared_float_are_single_precision(self):
        src = """derivation length: 3;
module A(float);
Axiom: A(0);
A(t): { produce A(t + 0.1); }
"""
        r = run_lpfg(src)
        self.assertEqual(r["lstring"], "A(0.30000001192092896)")

    def test_if_else_chains(self):
        body = "int a = 5; if (a < 3) result = 1; else if (a < 6) result = 2; else result = 3;"
        self.assertEqual(result_of(body), 2.0)

    def test_while_do_and_for_with_break_and_continue(self):
        self.assertEqual(result_of("int i = 0; while (i < 10) i += 3; result = i;"), 12.0)
        self.assertEqual(result_of("int i = 0; do { i++; } while (i < 0); result = i;"), 1.0)
        body = "int s = 0; for (int i = 0; i < 10; i++) { if (i % 2) continue; if (i > 6) break; s += i; } result = s;"
        self.assertEqual(result_of(body), 0 + 2 + 4 + 6)

    def test_switch_falls_through_until_break(self):
        body = "int s = 0; switch (2) { case 1: s += 1; case 2: s += 10; case 3: s += 100; break; default: s += 1000; } result = s;"
        self.assertEqual(result_of(body), 110.0)

    def test_increments_compound_assignments_and_the_ternary(self):
        body = "int i = 1; int j = i++ + ++i; i *= 2; i -= 1; i /= 2; result = j*100 + i + (j > 3 ? 0.5 : 0);"
        self.assertEqual(result_of(body), 400 + 2 + 0.5)

    def test_functions_and_arrays(self):
        decl = "float sq(float x) { return x*x; }\nint tab[4] = {1, 2, 3, 4};"
        self.assertEqual(result_of("result = sq(3) + tab[2];", decl), 12.0)

    def test_a_block_variable_shadows_without_changing_the_outer_one(self):
        self.assertEqual(result_of("int a = 1; { int a = 2; a++; } result = a;"), 1.0)

    def test_structs_are_values_copied_on_assignment(self):
        decl = "struct P { float x, y; };"
        body = "P a = {1, 2}; P b = a; b.x = 10; result = a.x + b.x + b.y;"
        self.assertEqual(result_of(body, decl), 13.0)

    def test_struct_constructors_and_methods(self):
        decl = "struct C { int n; C(int k) { n = k * 2; } int twice() { return n * 2; } };"
        self.assertEqual(result_of("C c(3); result = c.twice();", decl), 12.0)

    def test_vectors_with_lpfg_methods(self):
        body = "V3f a(3, 4, 0); V3f b = a * 2.0; result = b.Length() + (a % V3f(0, 0, 1)).x;"
        self.assertEqual(result_of(body), 10.0 + 4.0)

    def test_maths_is_in_radians(self):
        self.assertAlmostEqual(result_of("result = sin(M_PI/2) + pow(2, 3) + fabs(-1) + floor(2.5);"), 12.0)

    def test_globals_change_in_start_and_each_step(self):
        src = """#include <lpfgall.h>
int n;
derivation length: 3;
Start: { n = 10; }
EndEach: { n++; }
module A();
Axiom: A;
A(): { produce F(n) A; }
"""
        self.assertEqual(values(src), [10.0, 11.0, 12.0])


if __name__ == "__main__":
    unittest.main()

"""L-Py semantics, each on a small model whose result is counted by hand."""

import unittest

from lpy_helpers import count, run_text


class Productions(unittest.TestCase):
    def test_koch_curve_has_four_to_the_n_segments(self):
        r = run_text("Axiom: F\nderivation length: 3\nproduction:\nF --> F+F--F+F\nendlsystem\n")
        self.assertTrue(r["ok"], r["error"])
        self.assertEqual(r["steps"], 3)
        self.assertEqual(count(r["lstring"], "F"), 4 ** 3)

    def test_parameters_and_python_expressions(self):
        r = run_text("s = 2\nAxiom: A(1)\nderivation length: 2\nproduction:\n"
                     "A(x) --> F(x*s)[+(30)A(x+1)]\nendlsystem\n")
        self.assertEqual(r["lstring"], "F(2)[+(30)F(4)[+(30)A(3)]]")

    def test_body_with_produce_nproduce_and_no_production(self):
        src = ("Axiom: A(0)\nderivation length: 4\nproduction:\nA(i) :\n"
               "    if i % 2 == 0:\n        nproduce F(i)\n        produce A(i+1)\n"
               "    elif i < 3:\n        nproduce G A(i+1)\n    # i == 3: no production, A stays\n"
               "endlsystem\n")
        r = run_text(src)
        self.assertEqual(r["lstring"], "F(0)GF(2)A(3)")
        self.assertEqual(r["steps"], 4)

    def test_empty_production_erases_and_star_too(self):
        r = run_text("Axiom: A B C\nderivation length: 1\nproduction:\nA -->\nB :\n  produce *\nendlsystem\n")
        self.assertEqual(r["lstring"], "C")

    def test_declared_modules_named_parameters_and_aliases(self):
        src = ("module Apex(age, size)\nmodule Top = Apex\nAxiom: Apex(1, 2)\n"
               "derivation length: 1\nproduction:\nApex(a, s) :\n  m = Apex(a, s)\n"
               "  produce Internode(m.size) Top(a + 1, s)\nendlsystem\n")
        r = run_text(src.replace("m = Apex(a, s)", "m = ParamModule('Apex', [a, s])"))
        self.assertTrue(r["ok"], r["error"])
        # Internode is not declared: it reads as the letters I n t e r n o d e
        self.assertIn("Apex(2,2)", r["lstring"])
        self.assertEqual(count(r["lstring"], "I"), 1)

    def test_first_matching_rule_in_file_order_wins(self):
        r = run_text("Axiom: A(1) A(5)\nderivation length: 1\nproduction:\n"
                     "A(x) :\n  if x > 2: produce B\nA(x) --> C\nendlsystem\n")
        self.assertEqual(r["lstring"], "CB")

    def test_derivation_length_expression_and_steps_option(self):
        src = "n = 2\nAxiom: A\nderivation length: n + 1\nproduction:\nA --> AF\nendlsystem\n"
        self.assertEqual(count(run_text(src)["lstring"], "F"), 3)
        self.assertEqual(count(run_text(src, steps=5)["lstring"], "F"), 5)

    def test_every_step_runs_even_when_no_rule_applies(self):
        # L-Py's option "Early return when no matching" is Disabled by default
        src = ("n = []\ndef EndEach():\n  n.append(1)\ndef End(s):\n  return s + [('F', len(n))]\n"
               "Axiom: A(0)\nderivation length: 10\nproduction:\n"
               "A(x) :\n  if x < 2: produce A(x+1)\nendlsystem\n")
        r = run_text(src)
        self.assertEqual(r["steps"], 10)
        self.assertEqual(r["lstring"], "A(2)F(10)")


    def test_get_module_binds_and_emits_the_whole_module(self):
        src = ("module Aging(age)\nAxiom: Aging(1) B\nderivation length: 2\nproduction:\n"
               "$Aging(a):\n  a.age += 1\n  produce $a F(a.age,\n     2)\nendlsystem\n")
        r = run_text(src)
        self.assertTrue(r["ok"], r["error"])
        self.assertEqual(r["lstring"], "Aging(3)F(3,2)F(2,2)B")

    def test_successor_continued_on_later_lines_keeps_line_numbers(self):
        src = ("Axiom: A\nderivation length: 1\nproduction:\nA --> F(1,\n  2) B(1/0 if False else 1)\n"
               "B --> C(1/0)\nendlsystem\n")
        r = run_text(src.replace("Axiom: A", "Axiom: A B"))
        self.assertEqual(r["error"]["line"], 6)


class Contexts(unittest.TestCase):
    def test_left_context_skips_branches_and_climbs_to_the_parent(self):
        r = run_text("Axiom: A[B][C D]E\nderivation length: 1\nproduction:\n"
                     "A < E --> X\nA < D --> Y\nA < C --> Z\nendlsystem\n")
        self.assertEqual(r["lstring"], "A[B][ZD]X")

    def test_right_context_skips_branches_and_enters_them(self):
        r = run_text("Axiom: A[B]C\nderivation length: 1\nproduction:\n"
                     "A > C --> X\nB > C --> Y\nendlsystem\n")
        self.assertEqual(r["lstring"], "X[B]C")
        r = run_text("Axiom: A[B]C\nderivation length: 1\nproduction:\nA > [B]C --> X\nendlsystem\n")
        self.assertEqual(r["lstring"], "X[B]C")

    def test_ignore_and_consider(self):
        r = run_text("Axiom: A+B\nignore: +\nderivation length: 1\nproduction:\nA > B --> X\nendlsystem\n")
        self.assertEqual(r["lstring"], "X+B")
        r = run_text("Axiom: A+C B\nconsider: A B\nderivation length: 1\nproduction:\nA > B --> X\nendlsystem\n")
        self.assertEqual(r["lstring"], "X+CB")

    def test_two_module_left_context_fibonacci(self):
        src = ("Axiom: I(1) I(1) I(0) I(0) I(0)\nderivation length: 3\nproduction:\n"
               "I(j) I(k) < I(i) --> I(j+k)\nendlsystem\n")
        # parallel rewriting: contexts read the previous string
        # I1 I1 I0 I0 I0 → I1 I1 I2 I1 I0 → I1 I1 I2 I3 I3 → I1 I1 I2 I3 I5
        self.assertEqual(run_text(src)["lstring"], "I(1)I(1)I(2)I(3)I(5)")

    def test_parameter_test_in_a_pattern(self):
        src = ("Any = -1\nAxiom: P(1, -1) P(2, 5)\nderivation length: 1\nproduction:\n"
               "P(v, s != Any) --> Q(v)\nendlsystem\n")
        self.assertEqual(run_text(src)["lstring"], "P(1,-1)Q(2)")

    def test_star_predecessor_binds_name_and_arguments(self):
        src = ("Axiom: A(1) B(2, 3)\nderivation length: 1\nproduction:\n"
               "*(n, *args) --> X(n, len(args))\nendlsystem\n")
        self.assertEqual(run_text(src)["lstring"], "X('A',1)X('B',2)")

    def test_cut_removes_the_rest_of_the_branch(self):
        r = run_text("Axiom: F[F%FF[F]F]F\nderivation length: 1\nproduction:\nendlsystem\n")
        self.assertEqual(r["lstring"], "F[F%FF[F]F]F")  # no rule: nothing rewritten
        r = run_text("Axiom: F[F%FF[F]F]F\nderivation length: 1\nproduction:\nF --> F\nendlsystem\n")
        self.assertEqual(r["lstring"], "F[F]F")


class Phases(unittest.TestCase):
    def test_decomposition_to_its_maximum_depth(self):
        src = ("Axiom: A(3)\nderivation length: 1\nproduction:\ndecomposition:\nmaximum depth: 2\n"
               "A(n) :\n  if n > 0: produce F A(n-1)\nendlsystem\n")
        self.assertEqual(run_text(src)["lstring"], "FFA(1)")

    def test_interpretation_is_applied_to_the_result_only(self):
        src = ("Axiom: A\nderivation length: 2\nproduction:\nA --> AB\n"
               "interpretation:\nB --> F(2)\nendlsystem\n")
        self.assertEqual(run_text(src)["lstring"], "AF(2)F(2)")

    def test_homomorphism_maximum_depth(self):
        src = ("Axiom: X\nderivation length: 0\nhomomorphism:\nmaximum depth: 2\n"
               "X --> Y Y\nY --> F\nendlsystem\n")
        self.assertEqual(run_text(src)["lstring"], "FF")

    def test_groups_and_use_group(self):
        src = ("def EndEach():\n  useGroup(1 if getIterationNb() == 0 else 0)\n"
               "Axiom: A\nderivation length: 3\nproduction:\nA --> AF\n"
               "group 1:\nA --> AG\nendgroup\nendlsystem\n")
        # step 0 group 0: AF; step 1 group 1 (its rule first): AGF; step 2 group 0: AFGF
        self.assertEqual(run_text(src)["lstring"], "AFGF")


class Hooks(unittest.TestCase):
    def test_start_starteach_endeach_end_and_iteration_number(self):
        src = ("seen = []\ndef Start():\n  seen.append('S')\n"
               "def StartEach():\n  seen.append(getIterationNb())\n"
               "def EndEach(lstring):\n  return lstring + [('F', len(seen))]\n"
               "def End(lstring):\n  return Lstring(str(len(lstring)) and 'G(9)') + lstring\n"
               "Axiom: A\nderivation length: 2\nproduction:\nA --> A\nendlsystem\n")
        r = run_text(src)
        self.assertTrue(r["ok"], r["error"])
        self.assertEqual(r["lstring"], "G(9)AF(2)F(3)")

    def test_stop_ends_the_derivation(self):
        src = ("def EndEach():\n  if getIterationNb() == 1: Stop()\n"
               "Axiom: A\nderivation length: 10\nproduction:\nA --> AF\nendlsystem\n")
        r = run_text(src)
        self.assertEqual(r["steps"], 2)
        self.assertEqual(count(r["lstring"], "F"), 2)

    def test_backward_direction(self):
        src = ("backward()\nAxiom: A B C\nderivation length: 1\nproduction:\n"
               "B << C --> X\nA --> Y\nendlsystem\n")
        r = run_text(src)
        self.assertTrue(r["ok"], r["error"])
        self.assertIn("Y", r["lstring"])

    def test_repetition_over_child_branches_in_the_new_string(self):
        # backwards, the branches to A's right are already rewritten when A is: 10 + 20
        src = ("def Start():\n  backward()\nAxiom: A [B(1)] [B(2)] [C] B(9)\nderivation length: 1\n"
               "production:\nB(w) --> B(w*10)\nA >> x([B(w)]) --> A(sum(w))\nendlsystem\n")
        r = run_text(src)
        self.assertTrue(r["ok"], r["error"])
        self.assertEqual(r["lstring"], "A(30)[B(10)][B(20)][C]B(90)")

    def test_axiom_as_python_body(self):
        r = run_text("Axiom:\n  for i in range(3): nproduce F(i)\nderivation length: 0\nendlsystem\n")
        self.assertEqual(r["lstring"], "F(0)F(1)F(2)")


class Initialisation(unittest.TestCase):
    SRC = ("Axiom: F(length)\nderivation length: 0\nendlsystem\n"
           "###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\n"
           "def __initialiseContext__(context):\n"
           "\timport openalea.plantgl.all as pgl\n"
           "\tColor_1 = pgl.Material('Color_1', ambient = (30,60,10), diffuse = 3)\n"
           "\tcontext.turtle.setMaterial(1,Color_1)\n"
           "\tscalars = [('length', 'Float', 2.5, 0, 10, 2)]\n"
           "\tcontext['__scalars__'] = scalars\n"
           "\tcurve = pgl.NurbsCurve2D(pgl.Point3Array([(0,0,1),(1,1,1),(2,0,1)]), degree=2)\n"
           "\tcontext['curve'] = curve\n")

    def test_materials_scalars_and_curves(self):
        r = run_text(self.SRC)
        self.assertTrue(r["ok"], r["error"])
        self.assertEqual(r["materials"], [{"index": 1, "rgb": [90, 180, 30]}])
        self.assertEqual(r["lstring"], "F(2.5)")

    def test_curve_objects_are_referenced(self):
        # (a SetGuide is written out as the turns it makes: test_turtle_guide.py)
        r = run_text(self.SRC.replace("Axiom: F(length)", "Axiom: SetContour(curve) F(1)"))
        self.assertTrue(r["lstring"].startswith("SetContour(@obj0)"), r["lstring"])
        self.assertEqual(r["objects"][0]["type"], "NurbsCurve2D")
        self.assertEqual(r["objects"][0]["points"][0], [0.0, 0.0])
        self.assertEqual(r["objects"][0]["points"][-1], [2.0, 0.0])


class Randomness(unittest.TestCase):
    SRC = ("from random import *\nAxiom: A\nderivation length: 5\nproduction:\n"
           "A :\n  if random() < 0.5: produce F A\n  else: produce G A\nendlsystem\n")

    def test_same_seed_same_plant_other_seed_other_plant(self):
        a, b = run_text(self.SRC, seed=1), run_text(self.SRC, seed=1)
        self.assertEqual(a["lstring"], b["lstring"])
        others = {run_text(self.SRC, seed=s)["lstring"] for s in range(2, 12)}
        self.assertGreater(len(others), 1)

    def test_it_is_pythons_random(self):
        import random

        random.seed(7)
        expected = "".join("F" if random.random() < 0.5 else "G" for _ in range(5)) + "A"
        self.assertEqual(run_text(self.SRC, seed=7)["lstring"], expected)


class FilesAndNotes(unittest.TestCase):
    def test_open_reads_the_models_own_files(self):
        from lpy_helpers import run

        main = ("with open('data/lengths.txt') as f:\n  L = [float(x) for x in f.read().split()]\n"
                "Axiom: A\nderivation length: 1\nproduction:\nA :\n"
                "  for l in L: nproduce F(l)\nendlsystem\n")
        r = run({"main.lpy": main, "lengths.txt": "1 2.5"}, "main.lpy", {})
        self.assertEqual(r["lstring"], "F(1.0)F(2.5)")
        r = run({"main.lpy": main}, "main.lpy", {})
        self.assertEqual(r["error"]["line"], 1)
        self.assertIn("FileNotFoundError", r["error"]["message"])

    def test_unavailable_pattern_leaves_its_rule_out_with_a_note(self):
        src = ("Axiom: A B\nderivation length: 1\nproduction:\nA >> x([?I(it)]) --> X\n"
               "A --> Y\nendlsystem\n")
        r = run_text(src)
        self.assertTrue(r["ok"], r["error"])
        self.assertEqual(r["lstring"], "YB")
        self.assertEqual(r["notes"][0]["line"], 4)


class Composition(unittest.TestCase):
    def test_lsystem_from_another_file(self):
        from lpy_helpers import run

        other = "Axiom: B\nderivation length: 2\nproduction:\nB --> BF\nendlsystem\n"
        main = ("sub = Lsystem('other.lpy')\nAxiom: A\nderivation length: 1\nproduction:\n"
                "A :\n  nproduce G\n  return sub.derive(sub.axiom, 2)\nendlsystem\n")
        r = run({"main.lpy": main, "other.lpy": other}, "main.lpy", {})
        self.assertTrue(r["ok"], r["error"])
        self.assertEqual(r["lstring"], "GBFF")


if __name__ == "__main__":
    unittest.main()

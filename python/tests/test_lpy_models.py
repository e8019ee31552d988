"""Ten models of L-Py's own collection, checked against a hand count of what they draw.

The files come from the collection copied into the repository (crate/tests/collections/lpy,
from openalea/lpy at commit 4a365a3, CeCILL-C), copied in crate/tests/collections/lpy;
a test is skipped only when neither copy exists."""

import re
import unittest

from lpy_helpers import collection_file, count, run


def derive(test, source_path, **options):
    found = collection_file(source_path)
    if found is None:
        test.fail(f"{source_path} is not in crate/tests/collections/lpy: the hand counts need it")
    name, text = found
    result = run({name: text}, name, options)
    test.assertTrue(result["ok"], result["error"])
    return result


class CollectionModels(unittest.TestCase):
    def test_abop_fig_1_4_twenty_axes_of_twenty_segments(self):
        # A(i) makes B(0,i) for i < 20; each B adds one F a step for 20 steps; 40 steps: 20 × 20
        r = derive(self, "share/abop/chap1/lsystem1.4.lpy")
        self.assertEqual(count(r["lstring"], "F"), 400)
        self.assertEqual(count(r["lstring"], ","), 20)  # interpretation: B → ,(colour)

    def test_abop_fig_1_37_four_segments_per_segment(self):
        r = derive(self, "share/abop/chap1/lsystem-fig1.37.lpy")
        self.assertEqual(count(r["lstring"], "F"), 4 ** 5)

    def test_koch_curve(self):
        r = derive(self, "share/training/03-koch-curve.lpy")
        self.assertEqual(count(r["lstring"], "F"), 4 ** 5)

    def test_von_koch_default_derivation_length_is_one(self):
        r = derive(self, "share/examples/ex_vonkoch.lpy")
        self.assertEqual(r["steps"], 1)
        self.assertEqual(count(r["lstring"], "F"), 4)

    def test_hilbert_curve_and_its_angle_increment(self):
        r = derive(self, "share/tutorial/02 - fractals/hilbert-curve.lpy")
        self.assertEqual(count(r["lstring"], "F"), 4 ** 5 - 1)
        self.assertEqual(r["turtle"]["angle_increment"], 90.0)

    def test_dragon_curve(self):
        r = derive(self, "share/tutorial/02 - fractals/dragoncurve.lpy")
        self.assertEqual(count(r["lstring"], "F"), 2 ** 10)

    def test_gosper_curve_interpreted(self):
        # A and B each rewrite into 7 letters; interpretation draws each as F
        r = derive(self, "share/tutorial/02 - fractals/gosper.lpy")
        self.assertEqual(count(r["lstring"], "F"), 7 ** 4)
        self.assertEqual(count(r["lstring"], "A"), 0)

    def test_sierpinski_triangles_as_polygons(self):
        r = derive(self, "share/training/04-sierpinski.lpy")
        self.assertEqual(count(r["lstring"], "{"), 3 ** 5)
        self.assertEqual(count(r["lstring"], "F"), 2 * 3 ** 5)

    def test_cantor_set(self):
        r = derive(self, "share/tutorial/02 - fractals/cantorset.lpy")
        self.assertEqual(count(r["lstring"], "F"), 2 ** 5)
        self.assertEqual(count(r["lstring"], "f"), 2 ** 5 - 1)

    def test_fibonacci_by_left_context_and_decomposition(self):
        r = derive(self, "share/training/13-fibonacci.lpy")
        labels = [int(x) for x in re.findall(r"@L\('(\d+)'\)", r["lstring"])]
        fib = [1, 1]
        while len(fib) < 20:
            fib.append(fib[-1] + fib[-2])
        self.assertEqual(labels, fib)

    def test_pascal_triangle_row(self):
        r = derive(self, "models/pascaltriangle/pascaltriangle1.lpy")
        labels = [int(x) for x in re.findall(r"@L\('(\d+)'\)", r["lstring"])]
        from math import comb

        n = len(labels) - 1
        self.assertGreater(n, 3)
        self.assertEqual(labels, [comb(n, k) for k in range(n + 1)])


if __name__ == "__main__":
    unittest.main()

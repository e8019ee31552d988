"""PlantGL's guides, nF, Sweep and Discretizer, on small models counted and computed by hand."""

import math
import re
import unittest

from lpy_helpers import collection_file, count, run_text

from meristem_lsystem import run
from meristem_lsystem.lpy_lstring import NameTable, parse_modules
from meristem_lsystem.lstring import predefined_names

HEADER = "from openalea.plantgl.all import *\n"


def _value(text):
    try:
        return float(text) if "." in text or "e" in text else int(text)
    except ValueError:
        return text


def modules(lstring):
    """(name, [parameters]) of each module, numbers read back."""
    return [(m.name, [_value(a.strip()) for a in m.args.split(",")] if m.args else [])
            for m in parse_modules(lstring, NameTable(predefined_names()))]


class Guides(unittest.TestCase):
    def run_axiom(self, setup, axiom):
        r = run_text(HEADER + setup + f"Axiom: {axiom}\nderivation length: 0\nendlsystem\n")
        self.assertTrue(r["ok"], r["error"])
        return modules(r["lstring"])

    def test_a_corner_of_the_guide_turns_the_turtle_by_the_chord_then_the_tangent(self):
        # Polyline (0,0) (1,0) (1,1), length 2 = its own length (scale 1). F(0.5) reaches (0.5, 0)
        # straight; F(1) goes to (1, 0.5): a chord at 45° (turn 45° toward the curve's y, which
        # is the turtle's up: &(-45)), of length √0.5, then the tangent (0, 1): another 45°.
        got = self.run_axiom("c = Polyline2D([(0,0),(1,0),(1,1)])\n", "SetGuide(c, 2) F(0.5) F(1)")
        self.assertEqual(got[0], ("F", [0.5]))
        self.assertEqual([n for n, _ in got], ["F", "&", "F", "&"])
        self.assertAlmostEqual(got[1][1][0], -45.0, places=9)
        self.assertAlmostEqual(got[2][1][0], math.sqrt(0.5), places=12)
        self.assertAlmostEqual(got[3][1][0], -45.0, places=9)

    def test_scale_y_orientation_and_brackets(self):
        # a straight guide of length 1 mapped to 2: F(1) covers half the curve, moves 0.5 · 2
        got = self.run_axiom("c = Polyline2D([(0,0),(1,0)])\n", "[SetGuide(c, 2) F(1)] F(1)")
        self.assertEqual(got, [("[", []), ("F", [1.0]), ("]", []), ("F", [1])])
        # y orientation: the curve's x is the turtle's left side; a turn about up (+)
        got = self.run_axiom("c = Polyline2D([(0,0),(0,1),(1,1)])\n", "SetGuide(c, 2, True) F(0.5) F(1)")
        self.assertEqual([n for n, _ in got], ["F", "+", "F", "+"])
        self.assertAlmostEqual(got[1][1][0], -45.0, places=9)

    def test_the_guide_ends_with_its_length(self):
        got = self.run_axiom("c = Polyline2D([(0,0),(1,0)])\n", "SetGuide(c, 1) F(1) F(1) EndGuide F(2)")
        self.assertEqual(got, [("F", [1.0]), ("F", [1]), ("F", [2])])

    def test_sweep_is_guide_contour_and_nf_with_widths(self):
        # nF(1, 0.25, radius 1) from PlantGL's default width 0.1: widths 0.1 + 0.9·k/4
        got = self.run_axiom("c = Polyline2D([(0,0),(1,0)])\ns = Polyline2D.Circle(1, 4)\n",
                             "Sweep(c, s, 1, 0.25)")
        self.assertEqual(got[0][0], "SetContour")
        widths = [a[1] for n, a in got if n == "F"]
        for w, want in zip(widths, (0.325, 0.55, 0.775, 1.0)):
            self.assertAlmostEqual(w, want, places=12)
        self.assertEqual(len(widths), 4)

    def test_nf_with_a_radius_variation(self):
        setup = "f = QuantisedFunction(Polyline2D([(0,1),(1,3)]))\n"
        got = self.run_axiom(setup, "nF(1, 0.5, 2, f)")
        self.assertEqual(got[0][0], "SetWidth")
        self.assertAlmostEqual(got[0][1][0], 2.0)
        self.assertEqual([round(a[1], 9) for n, a in got if n == "F"], [4.0, 6.0])

    def test_discretizer_of_a_nurbs_curve(self):
        src = (HEADER + "c = NurbsCurve2D([(0,0,1),(1,1,1),(2,0,1)], stride=4)\nd = Discretizer()\n"
               "c.apply(d)\np = d.result.pointList\nAxiom: F(len(p)) F(p[2][0]) F(p[4][0])\n"
               "derivation length: 0\nendlsystem\n")
        r = run_text(src)
        self.assertTrue(r["ok"], r["error"])
        self.assertEqual(r["lstring"], "F(5)F(1.0)F(2.0)")


class CollectionModels(unittest.TestCase):
    def run_model(self, path):
        found = collection_file(path)
        self.assertIsNotNone(found, path)
        name, text = found
        r = run({name: text}, name, {})
        self.assertTrue(r["ok"], r["error"])
        return r

    def test_sweepsurface_draws_length_over_dl_segments(self):
        # Sweep(path, section, length 1, dl 0.01, ...): PlantGL's nF, int(1 / 0.01) = 100 F
        r = self.run_model("share/tutorial/01 - turtle/07 - sweepsurface.lpy")
        self.assertEqual(count(r["lstring"], "F"), 100)
        self.assertNotIn("Sweep", r["lstring"])

    def test_orchidee_draws_its_stem_leaves_and_flowers(self):
        # 13 internodes, 5 basal F(0.1), 18 leaves of 100 F; with NFlowerClosed = 4 (the model's
        # own line after its panel): 4 closed flowers (peduncle 9 F, 3 sepals of 100 F) and 4 open
        # (peduncle 9, sepals 300, F(0.5), petals 200, upper and lower lips 100 each)
        # The lower lips' hairs: `?F(p,h,u,l) Section(...)` reads the turtle's frame (filled
        # before each step), each hair `[MoveRel(...) SetHead(n, h) _ F(0.2,0.001)]` with n made
        # of l and u, so n ⟂ h and |h| = 1 when the frame is PlantGL's orthonormal frame.
        r = self.run_model("share/tutorial/10 - graphics/orchidee.lpy")
        want = 13 + 5 + 18 * 100 + 4 * (9 + 300) + 4 * (9 + 300 + 1 + 200 + 200)
        hairs = re.findall(r"\[MoveRel\([^)]*\)@R\(([^)]*)\)", r["lstring"])
        self.assertGreater(len(hairs), 62 * 4)  # 62 sections on each of the 4 lower lips
        self.assertEqual(count(r["lstring"], "F"), want + len(hairs))
        for hair in hairs:
            n, h = [float(v) for v in hair.split(",")[:3]], [float(v) for v in hair.split(",")[3:]]
            self.assertAlmostEqual(sum(a * b for a, b in zip(n, h)), 0.0, places=9)
            self.assertAlmostEqual(sum(a * a for a in h), 1.0, places=9)
        self.assertFalse(any("?F" in n["message"] for n in r["notes"]))
        self.assertIsNone(re.search(r"SetGuide|nF\(", r["lstring"]))


if __name__ == "__main__":
    unittest.main()

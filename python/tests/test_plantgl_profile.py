"""PlantGL's CSpline and InterpolatedProfile (plantgl_cspline, plantgl_profile), values computed
by hand, and L-Py's lsystem10 (branches guided by interpolated sections) counted by hand."""

import unittest

from lpy_helpers import collection_file

from meristem_lsystem import run
from meristem_lsystem.lpy_lstring import NameTable, parse_modules
from meristem_lsystem.lstring import predefined_names
from meristem_lsystem.plantgl_cspline import cspline
from meristem_lsystem.plantgl_profile import CrossSection, CSplineMethod, InterpolatedProfile


def profile():
    tc = InterpolatedProfile(CSplineMethod)
    tc.add_cross_sections(0.0, CrossSection((0, 0), (1, 0)),
                          0.5, CrossSection((0, 2), (1, 1)),
                          1.0, CrossSection((0, 0), (1, 4)))
    return tc


class CSplines(unittest.TestCase):
    def test_knots_are_cumulated_distances_and_the_curve_passes_through_the_points(self):
        c = cspline([(0, 0, 0), (3, 4, 0), (3, 4, 2)])
        # distances 5 and 2: knots 0, each of 0, 5, 7 three times, 7
        self.assertEqual(c.knotList, [0, 0, 0, 0, 5, 5, 5, 7, 7, 7, 7])
        self.assertEqual(len(c.ctrlPointList), 7)
        self.assertEqual(list(c.getPointAt(5)), [3, 4, 0])
        self.assertEqual(list(c.getPointAt(7)), [3, 4, 2])
        # the inner tangent is (P2 - P0) / 2 = (1.5, 2, 1): second control point P0 + D0 / 3
        self.assertEqual(list(c.ctrlPointList[1])[:3], [0.5, 2 / 3, 0])
        self.assertEqual(list(c.ctrlPointList[2])[:3], [2.5, 4 - 2 / 3, -1 / 3])


class Profiles(unittest.TestCase):
    def test_the_section_at_a_knot_is_the_given_section(self):
        section = profile().get_interpolated_section(0.5, False)
        self.assertEqual([list(p) for p in section], [[0, 2, 0.5], [1, 1, 0.5]])

    def test_between_knots_each_column_follows_its_cardinal_spline(self):
        # column P0, P1, P2 at t = 0, 0.5, 1 (knots from the differences 0.5, 0.5): at t = 0.25
        # the first Bezier arc P0, P0 + (P1 - P0)/6, P1 - (P2 - P0)/6, P1 at s = 1/2 gives
        # 0.5 P0 + 0.5625 P1 - 0.0625 P2: y = 0.5625 * 2 = 1.125 and 0.5625 * 1 - 0.0625 * 4
        section = profile()(0.25, False)
        self.assertAlmostEqual(section[0].y, 1.125)
        self.assertAlmostEqual(section[1].y, 0.3125)
        self.assertAlmostEqual(section[0].z, 0.5625 * 0.5 - 0.0625)
        # as a curve: the cardinal spline through those points
        curve = profile()(0.25)
        self.assertAlmostEqual(curve.getPointAt(curve.lastKnot).y, 0.3125)

    def test_sections_must_have_as_many_points_and_nurbs_method_is_refused(self):
        tc = profile()
        with self.assertRaisesRegex(Exception, "Wrong control point count"):
            tc.add_cross_section(0.75, CrossSection((0, 0), (1, 0), (2, 0)))
        with self.assertRaisesRegex(NotImplementedError, "NurbsMethod"):
            InterpolatedProfile.make_default()


def branch_counts(lstring):
    """F count at the top level and in each branch."""
    depth, top, branches = 0, 0, []
    for m in parse_modules(lstring, NameTable(predefined_names())):
        if m.name == "[":
            depth += 1
            branches.append(0)
        elif m.name == "]":
            depth -= 1
        elif m.name == "F":
            if depth == 0:
                top += 1
            else:
                branches[-1] += 1
    return top, branches


class Lsystem10(unittest.TestCase):
    def test_main_axis_and_branches_guided_by_the_interpolated_sections(self):
        found = collection_file("share/tutorial/lpy-paper12-examples/lsystem10.lpy")
        if found is None:
            self.skipTest("the L-Py collection is not copied")
        name, text = found
        r = run({name: text}, name, {})
        self.assertTrue(r["ok"], r["error"])
        top, branches = branch_counts(r["lstring"])
        # F(5), then one F(1) per step for 50 steps; a branch each step
        self.assertEqual(top, 51)
        self.assertEqual(len(branches), 50)
        # the first branch: lateral_length(0) = 0.14637 (its first control point), so its length
        # is 50 * 0.14637 = 7.3185 and M grows from 42.6815 to 50 by 1: 8 F
        self.assertEqual(branches[0], 8)
        # the last three are born at steps 48, 49, 50 and grow one F per remaining step
        self.assertEqual(branches[-3:], [2, 1, 0])
        # the guides are written out (turns and chords): no SetGuide left
        self.assertNotIn("SetGuide", r["lstring"])


if __name__ == "__main__":
    unittest.main()

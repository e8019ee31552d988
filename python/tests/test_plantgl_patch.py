"""PlantGL patches: points, exact tangents and normals checked against values computed by hand."""

import math
import unittest

from lpy_helpers import run_text  # noqa: F401  (puts the package on the path)

from meristem_lsystem.plantgl_patch import BezierPatch, NurbsPatch


def close(test, got, want, places=12):
    test.assertEqual(len(list(got)), len(want))
    for g, w in zip(got, want):
        test.assertAlmostEqual(g, w, places=places)


class BilinearPatch(unittest.TestCase):
    """S(u, v) = (u, v, u·v): S_u = (1, 0, v), S_v = (0, 1, u)."""

    def setUp(self):
        self.patch = NurbsPatch([[(0, 0, 0, 1), (0, 1, 0, 1)], [(1, 0, 0, 1), (1, 1, 1, 1)]], 1, 1)

    def test_point_and_tangents(self):
        close(self, self.patch.getPointAt(0.5, 0.25), [0.5, 0.25, 0.125])
        close(self, self.patch.getUTangentAt(0.5, 0.25), [1, 0, 0.25])
        close(self, self.patch.getVTangentAt(0.5, 0.25), [0, 1, 0.5])

    def test_normal_is_the_cross_product_of_the_normalised_tangents(self):
        # (1, 0, 0.5)/√1.25 × (0, 1, 0.5)/√1.25 = (−0.5, −0.5, 1)/1.25, norm √1.5/1.25 < 1
        close(self, self.patch.getNormalAt(0.5, 0.5), [-0.4, -0.4, 0.8])

    def test_rows_vary_with_u_as_in_plantgl(self):
        # row 1 of the matrix is u = 1: S(1, 0) is its first point
        close(self, self.patch.getPointAt(1, 0), [1, 0, 0])


class RationalQuarterCircle(unittest.TestCase):
    """Along u, the quarter circle (1,0) → (0,1) as a rational quadratic (weights 1, √2/2, 1);
    along v, a unit extrusion in z."""

    def setUp(self):
        w = math.sqrt(2) / 2
        rows = [[(1, 0, 0, 1), (1, 0, 1, 1)], [(1, 1, 0, w), (1, 1, 1, w)], [(0, 1, 0, 1), (0, 1, 1, 1)]]
        self.patch = NurbsPatch(rows, 2, 1)

    def test_points_lie_on_the_circle(self):
        for u in (0.1, 0.5, 0.9):
            p = self.patch.getPointAt(u, 0.3)
            self.assertAlmostEqual(p[0] ** 2 + p[1] ** 2, 1.0, places=12)
            self.assertAlmostEqual(p[2], 0.3, places=12)

    def test_end_tangent_of_a_rational_bezier(self):
        # C'(0) = p · w1/w0 · (P1 − P0) = 2 · √2/2 · (0, 1, 0)
        close(self, self.patch.getUTangentAt(0, 0), [0, math.sqrt(2), 0])
        close(self, self.patch.getVTangentAt(0, 0), [0, 0, 1])

    def test_tangent_is_perpendicular_to_the_radius_and_the_normal_points_out(self):
        p, t = self.patch.getPointAt(0.5, 0.3), self.patch.getUTangentAt(0.5, 0.3)
        self.assertAlmostEqual(p[0] * t[0] + p[1] * t[1], 0.0, places=12)
        s = math.sqrt(2) / 2
        close(self, self.patch.getNormalAt(0.5, 0.3), [s, s, 0])


class FlatPatchOfTheDiffGeometryModels(unittest.TestCase):
    """The plane x = 0 of `models/diffGeometry/flatpatch.lpy`: z = u, y = v − 0.5, written with
    control values 0.333333 and 0.166667 (six digits), so the tangents are 0.999999 long."""

    def test_tangents_and_normal(self):
        third, sixth = 0.333333, 0.166667
        zs, ys = (0, third, 1 - third, 1), (-0.5, -sixth, sixth, 0.5)
        patch = NurbsPatch([[(0, y, z, 1) for y in ys] for z in zs])
        close(self, patch.getUTangentAt(0, 0), [0, 0, 3 * third])
        close(self, patch.getVTangentAt(0, 0), [0, 3 * (0.5 - sixth), 0])
        close(self, patch.getNormalAt(0.3, 0.6), [-1, 0, 0])

    def test_degree_zero_direction_gives_zero_derivatives_as_plantgl(self):
        patch = NurbsPatch([[(0, 0, 0, 1)], [(1, 0, 0, 1)]], 1, 0)
        close(self, patch.getUTangentAt(0.5, 0), [0, 0, 0])


class Bezier(unittest.TestCase):
    def test_bezier_patch_is_the_same_surface(self):
        rows = [[(0, 0, 0), (0, 1, 0), (0, 2, 0)], [(1, 0, 1), (1, 1, 2), (1, 2, 1)]]
        b = BezierPatch(rows)
        # S(u, v) = (u, 2v, u·(1 + 2v(1 − v))): S_v = (0, 2, u(2 − 4v))
        close(self, b.getPointAt(0.5, 0.5), [0.5, 1, 0.75])
        close(self, b.getVTangentAt(1, 0.25), [0, 2, 1])


if __name__ == "__main__":
    unittest.main()

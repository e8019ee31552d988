"""PlantGL's cardinal spline: `NurbsCurve.CSpline(points, ...)`, a cubic NURBS through points.

Ported from PlantGL, `src/openalea/plantgl/scenegraph/cspline.py` (class `CSpline` and the
factory `cspline`, which PlantGL's `scenegraph/__init__.py` installs as the static method
`NurbsCurve.CSpline`), openalea/plantgl at commit 6e01c6db79ed1c61d81f71486a0a167105b8c0c4,
licence CeCILL-C (author C. Pradal, copyright CIRAD). Kept as PlantGL computes it:

- the tangent at an inner point is (P[i+1] - P[i-1]) / 2 (`_derivative1`; the distances are not
  used there), at the ends (P1 - P0) / 2 and (Pn - Pn-1) / 2;
- each arc is a cubic Bezier P[i], P[i] + D[i]/3, P[i+1] - D[i+1]/3, P[i+1];
- the knots are 0, then each cumulated distance three times, then the last again (the given
  `distances`, or the points' Euclidean distances; `is_linear` gives 0, 1, 2 … instead), so the
  curve passes through P[i] at the i-th cumulated distance;
- the result is a `NurbsCurve` (3D points, weight 1) or `NurbsCurve2D` (2D points) of degree 3
  with stride (n - 1) × 10.

The `degree` argument of `bezier_cp` is 3 when called from `curve` (as in PlantGL), so only the
knot vector follows `degree`. `NurbsSwung` (the rest of PlantGL's file) is not ported."""

from __future__ import annotations

from .plantgl_geometry import NurbsCurve, NurbsCurve2D, Point2Array, Point3Array, Point4Array
from .plantgl_math import Vector3, Vector4, norm

epsilon = 0.001


def _with_weight(points, w):
    """PlantGL's `Point4Array(points3, w)` / `Point3Array(points2, w)`: the points with weight w."""
    return [Vector4(p[0], p[1], p[2], w) if len(p) == 3 else Vector3(p[0], p[1], w) for p in points]


class CSpline:
    """A CSpline interpolates a set of points (PlantGL's `cspline.CSpline`)."""

    def __init__(self, points, is_closed=False):
        if len(points) != 0:
            self.dim = len(points[0])
            if self.dim == 2:
                self.points = Point2Array(points)
            elif self.dim == 3:
                self.points = Point3Array(points)
            elif self.dim == 4:
                self.points = Point4Array(points)
        else:
            self.dim = 3
            self.points = points
        self.is_closed = is_closed
        if is_closed:
            if norm(self.points[-1] - self.points[0]) > epsilon:
                self.points.append(self.points[0])
        self.nurbs = None
        self.dist = None
        self.der = None

    def __len__(self):
        return len(self.points)

    def distances(self):
        """The distances between consecutive input points."""
        self.dist = [norm(self.points[i + 1] - self.points[i]) for i in range(len(self) - 1)]

    def derivatives(self):
        """The tangents: D_i = (P_(i+1) - P_(i-1)) / 2 inside, half the end chords at the ends."""
        n = len(self.points)
        d0 = (self.points[1] - self.points[0]) / 2.0
        dn = (self.points[-1] - self.points[-2]) / 2.0
        if self.is_closed:
            d0 = dn = self._derivative1(self.points[-1], self.points[0], self.points[1],
                                        self.dist[-1], self.dist[0])
        self.der = [d0]
        for i in range(1, n - 1):
            p, q, r = self.points[i - 1], self.points[i], self.points[i + 1]
            self.der.append(self._derivative1(p, q, r, self.dist[i - 1], self.dist[i]))
        self.der.append(dn)

    def _derivative1(self, p, q, r, d0, d1):
        return (r - p) / 2.0

    def _derivative2(self, p, q, r, d0, d1):
        d = d0 + d1
        d0 /= d
        d1 /= d
        return (q - p) / (2 * d0) + (r - q) / (2 * d1)

    def bezier_cp(self, degree=3):
        """The Bezier control points: per arc P, P + D·a, Q − D'·a (a = 1/degree)."""
        if degree == 1:
            self.ctrl_pts = self.points
            return
        if degree not in (2, 3):
            return
        a = 1.0 / degree
        n = len(self)
        self.ctrl_pts = [0] * (3 * n - 2)
        for i in range(0, n - 1):
            p, q = self.points[i:i + 2]
            dp, dq = self.der[i:i + 2]
            self.ctrl_pts[i * 3] = p
            self.ctrl_pts[i * 3 + 1] = p + dp * a
            self.ctrl_pts[i * 3 + 2] = q - dq * a
        self.ctrl_pts[-1] = self.points[-1]
        if self.is_closed:
            self.ctrl_pts[1] = self.ctrl_pts[2]
            self.ctrl_pts[-2] = self.ctrl_pts[-3]

    def bezier_kv(self, is_linear=False, degree=3):
        """The knot vector: each cumulated distance `degree` times, clamped at both ends."""
        nb_pts = len(self.ctrl_pts)
        nb_arc = len(self) - 1
        assert nb_arc == (nb_pts - 1) / degree
        if is_linear:
            param = [float(i) for i in range(nb_arc + 1)]
            self.kv = [param[0]] * (degree + 1)
            step = (param[-1] - param[0]) / float(nb_arc)
            for i in range(1, nb_arc):
                self.kv.extend([param[0] + i * step] * degree)
            self.kv.extend([param[-1]] * (degree + 1))
            return
        dist = self.dist
        assert len(dist) == nb_arc
        param, p = [0.0], 0.0
        for d in dist:
            p += d
            param.append(p)
        # PlantGL rebuilds the vector inside its loop over the distances; the last one stays.
        self.kv = [param[0]] + [q for q in param for _ in range(degree)] + [param[-1]]

    def add_point(self, pt):
        if self.is_closed:
            raise Exception("Unable to add a point to a closed curve")
        self.points.append(pt)
        self.nurbs = None

    def move_point(self, i, pt):
        if i >= len(self):
            raise Exception("Index %d out of range [0,%d[" % (i, len(self)))
        self.points[i] = pt
        self.nurbs = None

    def curve(self, is_linear=False, degree=3, stride_factor=10, distances=None):
        """The PlantGL NURBS curve through the points."""
        if not self.nurbs:
            if distances is None:
                self.distances()
            else:
                self.dist = list(distances)
            self.derivatives()
            self.bezier_cp()
            self.bezier_kv(is_linear, degree)
        kv = list(self.kv)
        stride = (len(self.points) - 1) * stride_factor
        if self.dim == 3:
            self.nurbs = NurbsCurve(_with_weight(self.ctrl_pts, 1), kv, 3, stride)
        elif self.dim == 2:
            self.nurbs = NurbsCurve2D(_with_weight(self.ctrl_pts, 1), kv, 3, stride)
        else:
            raise Exception("Unable to build a spline curve from points of dimension %d" % (self.dim,))
        return self.nurbs


def cspline(pts, is_closed=False, is_linear=False, distances=None, degree=3):
    """A NURBS curve through `pts` (C1); PlantGL's `NurbsCurve.CSpline`."""
    spline = CSpline(pts, is_closed)
    return spline.curve(is_linear, degree=degree, distances=distances)

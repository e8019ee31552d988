"""PlantGL's NURBS and Bézier patches: points, exact partial derivatives, normals, iso-sections.

A `NurbsPatch` holds a matrix of control points (x, y, z, w); row i varies with u, column j
with v, as PlantGL's `getAt(row, col)` is read in its `NurbsPatch::getPointAt`. Points are
evaluated in homogeneous coordinates (x·w, y·w, z·w, w) by de Boor, along v within each row and
then along u. The tangents are the exact partial derivatives: the derivative of a B-spline curve
of degree p is the B-spline of degree p − 1 over the knots without their ends whose control
points are p (P[i+1] − P[i]) / (t[i+p+1] − t[i+1]) (Piegl & Tiller, The NURBS Book, eq. 3.8),
and a rational surface S = A / w has S_u = (A_u − w_u S) / w. As in PlantGL
(`src/cpp/plantgl/scenegraph/geometry/nurbspatch.cpp`, openalea/plantgl, CeCILL-C):
`getDerivativeAt` is zero when the order asked exceeds the smaller of the two degrees, and
`getNormalAt(u, v)` is the cross product of the two *normalised* tangents, not normalised again
(its norm is the sine of the angle between the tangents)."""

from __future__ import annotations

from .plantgl_geometry import NurbsCurve, Point4Matrix, _clamped_knots, _de_boor
from .plantgl_math import Vector3, Vector4


def _derivative(points: list[list[float]], knots: list[float], degree: int, u: float) -> list[float]:
    """The first derivative at `u` of the B-spline curve (non-rational: homogeneous points)."""
    if degree == 0:
        return [0.0] * len(points[0])
    q = []
    for i in range(len(points) - 1):
        den = knots[i + degree + 1] - knots[i + 1]
        q.append([degree * (b - a) / den if den else 0.0 for a, b in zip(points[i], points[i + 1])])
    return _de_boor(q, knots[1:-1], degree - 1, u)


def _homogeneous(p) -> list[float]:
    return [p[0] * p[3], p[1] * p[3], p[2] * p[3], p[3]]


class NurbsPatch:
    """A NURBS surface: rows of Vector4 control points (x, y, z, w)."""

    def __init__(self, ctrlPointMatrix, udegree=3, vdegree=3, uknotList=None, vknotList=None, **kw):
        self.ctrlPointMatrix = Point4Matrix(ctrlPointMatrix)
        rows, cols = len(self.ctrlPointMatrix), len(self.ctrlPointMatrix[0])
        self.udegree = min(int(kw.get("udegree", udegree)), rows - 1)
        self.vdegree = min(int(kw.get("vdegree", vdegree)), cols - 1)
        self.uknotList = list(uknotList) if uknotList else _clamped_knots(rows, self.udegree)
        self.vknotList = list(vknotList) if vknotList else _clamped_knots(cols, self.vdegree)

    def _rows_at(self, v):
        """Each row (fixed u index) blended at v: the homogeneous control points of a u-curve."""
        return [_de_boor([_homogeneous(p) for p in row], self.vknotList, self.vdegree, v)
                for row in self.ctrlPointMatrix]

    def _columns_at(self, u):
        """Each column (fixed v index) blended at u: the homogeneous control points of a v-curve."""
        return [_de_boor([_homogeneous(p) for p in col], self.uknotList, self.udegree, u)
                for col in zip(*self.ctrlPointMatrix)]

    def _homogeneous_at(self, u, v) -> list[float]:
        return _de_boor(self._rows_at(v), self.uknotList, self.udegree, u)

    def getPointAt(self, u, v):
        x, y, z, w = self._homogeneous_at(u, v)
        if abs(w) < 1e-10:  # PlantGL: GEOM_TOLERANCE, the homogeneous point as it is
            return Vector3(x, y, z)
        return Vector3(x / w, y / w, z / w)

    def _tangent(self, a: list[float], da: list[float]) -> Vector3:
        w = a[3] if abs(a[3]) >= 1e-10 else 1.0
        point = [c / w for c in a[:3]]
        return Vector3(*((dc - da[3] * pc) / w for dc, pc in zip(da[:3], point)))

    def getUTangentAt(self, u, v):
        """∂S/∂u at (u, v), exact."""
        if min(self.udegree, self.vdegree) < 1:
            return Vector3(0, 0, 0)
        rows = self._rows_at(v)
        return self._tangent(_de_boor(rows, self.uknotList, self.udegree, u),
                             _derivative(rows, self.uknotList, self.udegree, u))

    def getVTangentAt(self, u, v):
        """∂S/∂v at (u, v), exact."""
        if min(self.udegree, self.vdegree) < 1:
            return Vector3(0, 0, 0)
        cols = self._columns_at(u)
        return self._tangent(_de_boor(cols, self.vknotList, self.vdegree, v),
                             _derivative(cols, self.vknotList, self.vdegree, v))

    def getNormalAt(self, u, v):
        """PlantGL's normal: normalised u tangent × normalised v tangent (not normalised again)."""
        return self.getUTangentAt(u, v).normed() ^ self.getVTangentAt(u, v).normed()

    def getIsoUSectionAt(self, u):
        """The NURBS curve of the surface at `u` (control points: the columns blended at u)."""
        ctrl = []
        for x, y, z, w in self._columns_at(u):
            w = w or 1.0
            ctrl.append(Vector4(x / w, y / w, z / w, w))
        return NurbsCurve(ctrl, self.vknotList, self.vdegree)

    def getIsoVSectionAt(self, v):
        ctrl = []
        for x, y, z, w in self._rows_at(v):
            w = w or 1.0
            ctrl.append(Vector4(x / w, y / w, z / w, w))
        return NurbsCurve(ctrl, self.uknotList, self.udegree)

    def describe(self, count=12):
        grid = [[list(self.getPointAt(i / (count - 1), j / (count - 1))) for j in range(count)]
                for i in range(count)]
        return {"type": type(self).__name__, "points": grid}


class BezierPatch(NurbsPatch):
    """A Bézier patch: a NURBS patch of degrees (rows − 1, columns − 1) over clamped knots
    [0…0, 1…1], which evaluates to the same surface."""

    def __init__(self, ctrlPointMatrix, **kw):
        m = Point4Matrix(ctrlPointMatrix)
        super().__init__(m, len(m) - 1, len(m[0]) - 1)

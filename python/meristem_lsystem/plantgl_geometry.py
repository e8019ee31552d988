"""PlantGL's curves, patches, point arrays, materials and shapes that L-Py models build.

Curves are evaluated as PlantGL does: `NurbsCurve2D`/`NurbsCurve` by de Boor over a clamped
uniform knot vector unless knots are given (control points carry a weight as last coordinate),
`BezierCurve2D` by de Casteljau, `Polyline2D` piecewise linearly; `getPointAt(u)` takes u in
the curve's parameter range [firstKnot, lastKnot]. `QuantisedFunction(curve)` reads the curve as
y = f(x). A curve or patch in a module's parameters is written in the result as `@obj<k>` with
`describe()` in `result["objects"][k]`."""

from __future__ import annotations

import bisect

from .plantgl_math import Color3, Vector2, Vector3, Vector4, _Vector

SAMPLES = 32
DEFAULT_STRIDE = 30  # PlantGL: BezierCurve::DEFAULT_STRIDE, also NurbsCurve's


class _PointArray(list):
    KIND = Vector3

    def __init__(self, points=(), *more):
        if more or isinstance(points, (int, float)):
            points = [] if isinstance(points, (int, float)) else [points, *more]
        super().__init__(p if isinstance(p, _Vector) else self.KIND(*p) for p in points)

    def getLength(self):
        return len(self)


class Point2Array(_PointArray):
    KIND = Vector2


class Point3Array(_PointArray):
    KIND = Vector3


class Point4Array(_PointArray):
    KIND = Vector4


def _point4(p) -> Vector4:
    """A control point with its weight; three coordinates get weight 1."""
    values = list(p)
    return Vector4(*(values + [1.0] if len(values) == 3 else values))


class Point4Matrix(list):
    def __init__(self, rows=()):
        super().__init__([p if isinstance(p, Vector4) else _point4(p) for p in row] for row in rows)


def _clamped_knots(n: int, degree: int) -> list[float]:
    inner = n - degree - 1
    return [0.0] * (degree + 1) + [i / (inner + 1) for i in range(1, inner + 1)] + [1.0] * (degree + 1)


def _de_boor(points: list[list[float]], knots: list[float], degree: int, u: float) -> list[float]:
    n = len(points)
    u = min(max(u, knots[degree]), knots[n])
    k = bisect.bisect_right(knots, u) - 1
    k = min(max(k, degree), n - 1)
    d = [list(points[j + k - degree]) for j in range(degree + 1)]
    for r in range(1, degree + 1):
        for j in range(degree, r - 1, -1):
            i = j + k - degree
            den = knots[i + degree + 1 - r] - knots[i]
            a = 0.0 if den == 0 else (u - knots[i]) / den
            d[j] = [(1 - a) * x + a * y for x, y in zip(d[j - 1], d[j])]
    return d[degree]


class _Curve:
    DIM = 2
    name = ""

    def getPointAt(self, u):
        raise NotImplementedError

    @property
    def firstKnot(self):
        return 0.0

    @property
    def lastKnot(self):
        return 1.0

    def getTangentAt(self, u):
        h = (self.lastKnot - self.firstKnot) * 1e-4
        a = self.getPointAt(max(self.firstKnot, u - h))
        b = self.getPointAt(min(self.lastKnot, u + h))
        return (b - a).normed()

    def getNormalAt(self, u):
        t = self.getTangentAt(u)
        return Vector2(-t[1], t[0]) if self.DIM == 2 else Vector3(-t[1], t[0], 0)

    def sample(self, count=SAMPLES):
        a, b = self.firstKnot, self.lastKnot
        return [self.getPointAt(a + (b - a) * i / (count - 1)) for i in range(count)]

    def getStride(self):
        return int(getattr(self, "stride", DEFAULT_STRIDE))

    def getLength(self):
        """PlantGL's `LineicModel::getLength`: the polyline through `stride` + 1 points at
        uniform parameters."""
        a, b, n = self.firstKnot, self.lastKnot, self.getStride()
        pts = [self.getPointAt(a + (b - a) * i / n) for i in range(n + 1)]
        return sum((q - p).norm() for p, q in zip(pts, pts[1:]))

    def deepcopy(self):
        import copy

        return copy.deepcopy(self)

    def getArcLengthToUMapping(self):
        """PlantGL's `LineicModel::getArcLengthToUMapping`: normalised arc length in [0, 1] →
        the curve's parameter, from `stride` + 1 samples (repeated points skipped), quantised
        at 5 × stride."""
        a, b, n = self.firstKnot, self.lastKnot, self.getStride()
        total = self.getLength() or 1.0
        p1, length, points = self.getPointAt(a), 0.0, [(0.0, a)]
        for i in range(1, n + 1):
            u = a + (b - a) * i / n
            p2 = self.getPointAt(u)
            step = (p2 - p1).norm()
            if step > 0:
                length += step
                p1 = p2
                points.append((length / total, u))
        points[-1] = (1.0, b)
        return QuantisedFunction(Polyline2D(points), 5 * n)

    def apply(self, action):
        """`curve.apply(Discretizer())`: PlantGL's visitor, for the discretizer only."""
        return action.process(self)

    def describe(self):
        return {"type": type(self).__name__, "points": [list(p) for p in self.sample()]}


class NurbsCurve2D(_Curve):
    DIM = 2

    def __init__(self, ctrlPointList, knotList=None, degree=None, stride=None, **kw):
        if isinstance(knotList, int):  # PlantGL's other constructor: (points, degree, stride)
            knotList, degree, stride = None, knotList, degree
        degree = 3 if degree is None else degree
        stride = DEFAULT_STRIDE if stride is None else stride
        kind = Vector3 if self.DIM == 2 else Vector4
        pts = [p if isinstance(p, _Vector) else kind(*p) for p in ctrlPointList]
        self.ctrlPointList = pts
        self.degree = min(int(kw.get("degree", degree)), max(1, len(pts) - 1))
        self.knotList = list(knotList) if knotList else _clamped_knots(len(pts), self.degree)
        self.stride = stride

    @property
    def firstKnot(self):
        return self.knotList[self.degree]

    @property
    def lastKnot(self):
        return self.knotList[len(self.ctrlPointList)]

    def getPointAt(self, u):
        w_index = self.DIM
        homog = [[c * p[w_index] for c in list(p)[:w_index]] + [p[w_index]] for p in self.ctrlPointList]
        r = _de_boor(homog, self.knotList, self.degree, u)
        w = r[w_index] or 1.0
        coords = [c / w for c in r[:w_index]]
        return Vector2(*coords) if self.DIM == 2 else Vector3(*coords)


class NurbsCurve(NurbsCurve2D):
    DIM = 3


class BezierCurve2D(_Curve):
    DIM = 2

    def __init__(self, ctrlPointList, stride=DEFAULT_STRIDE, **kw):
        kind = Vector3 if self.DIM == 2 else Vector4
        self.ctrlPointList = [p if isinstance(p, _Vector) else kind(*p) for p in ctrlPointList]
        self.degree = len(self.ctrlPointList) - 1
        self.stride = stride

    def getPointAt(self, u):
        k = self.DIM
        pts = [[c * p[k] for c in list(p)[:k]] + [p[k]] for p in self.ctrlPointList]
        while len(pts) > 1:
            pts = [[(1 - u) * a + u * b for a, b in zip(p, q)] for p, q in zip(pts, pts[1:])]
        w = pts[0][k] or 1.0
        coords = [c / w for c in pts[0][:k]]
        return Vector2(*coords) if k == 2 else Vector3(*coords)


class BezierCurve(BezierCurve2D):
    DIM = 3


class Polyline2D(_Curve):
    DIM = 2

    def __init__(self, pointList, **kw):
        kind = Vector2 if self.DIM == 2 else Vector3
        self.pointList = [p if isinstance(p, _Vector) else kind(*p) for p in pointList]

    @property
    def lastKnot(self):
        return float(len(self.pointList) - 1)

    def getPointAt(self, u):
        pts = self.pointList
        i = min(max(int(u), 0), len(pts) - 2)
        t = u - i
        return pts[i] * (1 - t) + pts[i + 1] * t

    def sample(self, count=SAMPLES):
        return list(self.pointList)

    def getStride(self):
        return max(len(self.pointList) - 1, 1)

    @staticmethod
    def Circle(radius=1.0, slices=8):
        import math

        return Polyline2D([(radius * math.cos(2 * math.pi * i / slices),
                            radius * math.sin(2 * math.pi * i / slices)) for i in range(slices + 1)])


class Polyline(Polyline2D):
    DIM = 3


class QuantisedFunction:
    """A curve read as y = f(x), sampled as PlantGL does (`sampling` points, linear between)."""

    def __init__(self, curve, sampling=100, clamped=True):
        pts = sorted(((p[0], p[1]) for p in curve.sample(max(int(sampling), 2))), key=lambda p: p[0])
        self.xs, self.ys = [p[0] for p in pts], [p[1] for p in pts]
        self.clamped = clamped

    @property
    def firstx(self):
        return self.xs[0]

    @property
    def lastx(self):
        return self.xs[-1]

    def __call__(self, x):
        xs, ys = self.xs, self.ys
        if x <= xs[0]:
            return ys[0]
        if x >= xs[-1]:
            return ys[-1]
        i = bisect.bisect_right(xs, x)
        x0, x1 = xs[i - 1], xs[i]
        t = 0.0 if x1 == x0 else (x - x0) / (x1 - x0)
        return ys[i - 1] * (1 - t) + ys[i] * t

    getValue = __call__

    def describe(self):
        return {"type": "QuantisedFunction", "points": [[x, y] for x, y in zip(self.xs, self.ys)]}


class Discretizer:
    """PlantGL's Discretizer (`src/cpp/plantgl/algo/base/discretizer.cpp`) for curves: a
    NURBS or Bézier curve becomes the Polyline through `stride` + 1 points at uniform
    parameters (a 2D curve at z = 0), a Polyline2D the Polyline of its points. `result` holds it.
    Other shapes are not available and say so."""

    def __init__(self):
        self.result = None

    def process(self, shape):
        if isinstance(shape, Polyline2D):
            points = shape.pointList
        elif isinstance(shape, (NurbsCurve2D, BezierCurve2D)):
            a, b, n = shape.firstKnot, shape.lastKnot, shape.getStride()
            points = [shape.getPointAt(a + (b - a) * i / n) for i in range(n)] + [shape.getPointAt(b)]
        else:
            raise NotImplementedError(f"PlantGL's Discretizer of a {type(shape).__name__} is not available")
        self.result = Polyline([(*p, 0.0) if len(p) == 2 else tuple(p) for p in points])
        return True

    @property
    def discretization(self):
        return self.result


class Material:
    """A PlantGL material; its colour is ambient × diffuse, as PlantGL renders it."""

    def __init__(self, *args, **kw):
        self.name = ""
        self.ambient = Color3(80, 80, 80)
        self.diffuse = 2.0
        positional = list(args)
        if positional and isinstance(positional[0], str):
            self.name = positional.pop(0)
        fields = ["ambient", "diffuse", "specular", "emission", "shininess", "transparency"]
        for name, value in zip(fields, positional):
            kw.setdefault(name, value)
        for name, value in kw.items():
            if name in ("ambient", "specular", "emission") and not isinstance(value, Color3):
                value = Color3(*value)
            setattr(self, name, value)

    def rgb(self):
        return [min(255, max(0, round(c * self.diffuse))) for c in self.ambient]

    def describe(self):
        return {"type": "Material", "rgb": self.rgb()}


class ImageTexture(Material):
    def __init__(self, *args, **kw):
        super().__init__(*(a for a in args if not isinstance(a, str)))
        self.filename = next((a for a in args if isinstance(a, str)), "")


class Texture2D(Material):
    def __init__(self, *args, **kw):
        super().__init__()
        self.image = kw.get("image", args[0] if args else None)


class Point3Grid:
    """PlantGL's point grid for neighbourhood queries: points hashed into cubic voxels (the
    given voxel size, else about 8 points a voxel), balls and cones, points switched off."""

    def __init__(self, a, b=None, *rest):
        first_is_points = isinstance(a, (list, tuple)) and len(a) and not isinstance(a[0], (int, float))
        points, other = (a, b) if first_is_points else (b, a)
        self.points = [p if isinstance(p, _Vector) else Vector3(*p) for p in points]
        self.enabled = [True] * len(self.points)
        size = None
        if other is not None and not isinstance(other, (int, float)):
            size = max(float(x) for x in other)
        if not size and self.points:
            lo = [min(p[k] for p in self.points) for k in range(3)]
            hi = [max(p[k] for p in self.points) for k in range(3)]
            volume = max((hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]), 1e-9)
            size = (volume * 8 / len(self.points)) ** (1 / 3)
        self.size = size or 1.0
        self.cells: dict = {}
        for i, p in enumerate(self.points):
            self.cells.setdefault(self._cell(p), []).append(i)

    def _cell(self, p):
        k = self.size
        return (int(p[0] // k), int(p[1] // k), int(p[2] // k))

    def _near(self, center, radius):
        k = self.size
        lo = [int((center[d] - radius) // k) for d in range(3)]
        hi = [int((center[d] + radius) // k) for d in range(3)]
        cells = self.cells
        for x in range(lo[0], hi[0] + 1):
            for y in range(lo[1], hi[1] + 1):
                for z in range(lo[2], hi[2] + 1):
                    yield from cells.get((x, y, z), ())

    def query_ball_point(self, center, radius):
        c, r2 = Vector3(*center), float(radius) ** 2
        pts, on = self.points, self.enabled
        return sorted(i for i in self._near(c, float(radius)) if on[i] and (pts[i] - c).normSquared() <= r2)

    def query_points_in_cone(self, apex, direction, radius, angle):
        import math

        c, d = Vector3(*apex), Vector3(*direction).normed()
        r2, cos_max = float(radius) ** 2, math.cos(angle)
        found = []
        for i in self._near(c, float(radius)):
            if not self.enabled[i]:
                continue
            v = self.points[i] - c
            n2 = v.normSquared()
            if n2 <= r2 and (n2 == 0 or (v * d) / math.sqrt(n2) >= cos_max):
                found.append(i)
        return sorted(found)

    def disable_points(self, indices):
        for i in indices:
            self.enabled[i] = False

    def enable_points(self, indices):
        for i in indices:
            self.enabled[i] = True

    def is_point_enabled(self, i):
        return self.enabled[i]

    def get_enabled_points(self):
        return [p for p, on in zip(self.points, self.enabled) if on]

    def nbPoints(self):
        return len(self.points)


def pointset_mean_direction(origin, points, indices=None):
    """PlantGL: the mean of the unit directions from `origin` to the points (normalised)."""
    o = Vector3(*origin)
    chosen = [points[i] for i in indices] if indices is not None else list(points)
    total = Vector3(0, 0, 0)
    for p in chosen:
        total = total + (Vector3(*p) - o).normed()
    return total.normed()


def describe_value(v):
    """A parameter of a PlantGL shape as JSON: numbers, vectors as lists, shapes described."""
    if isinstance(v, (bool, int, float, str)) or v is None:
        return v
    if isinstance(v, _Vector) or isinstance(v, Color3):
        return list(v)
    describe = getattr(v, "describe", None)
    if describe is not None:
        return describe()
    if isinstance(v, (list, tuple)):
        return [describe_value(x) for x in v]
    return {"type": type(v).__name__}


class Geometry:
    """A PlantGL shape or transformation used with `@g`/`PglShape`: its type and arguments
    (`Scaled(size, BezierPatch(...))` → {"type": "Scaled", "args": [[…], {patch}]})."""

    PARAMETERS: tuple = ()  # PlantGL's names of the positional arguments

    def __init__(self, *args, **kw):
        object.__setattr__(self, "args", list(args))
        object.__setattr__(self, "kw", dict(kw))

    def __getattr__(self, name):
        params = type(self).PARAMETERS
        if name in params and params.index(name) < len(self.args):
            return self.args[params.index(name)]
        if name in self.kw:
            return self.kw[name]
        raise AttributeError(name)

    def __setattr__(self, name, value):
        params = type(self).PARAMETERS
        if name in params and params.index(name) < len(self.args):
            self.args[params.index(name)] = value
        else:
            self.kw[name] = value

    def describe(self):
        out = {"type": type(self).__name__, "args": [describe_value(a) for a in self.args]}
        if self.kw:
            out["named"] = {k: describe_value(v) for k, v in self.kw.items()}
        return out


GEOMETRY_NAMES = [
    "Sphere", "Cylinder", "Cone", "Box", "Disc", "Frustum", "Paraboloid", "Revolution",
    "Extrusion", "Translated", "Scaled", "AxisRotated", "EulerRotated", "Oriented", "Shape",
    "Scene", "TriangleSet", "QuadSet", "FaceSet", "Group", "Swung", "Text", "Font", "PointSet",
    "Polyline2DSet", "IFS", "ExtrudedHull", "Tapered", "BoundingBox", "Transformed", "Matrix4",
    "Quaternion", "ProfileInterpolation", "Font", "Index", "IndexArray", "Index3Array",
    "Index4Array", "Curve2DArray", "Color4Array", "RealArray", "Viewer",
]
SHAPE_PARAMETERS = {
    "Sphere": ("radius", "slices", "stacks"), "Cylinder": ("radius", "height", "solid", "slices"),
    "Cone": ("radius", "height", "solid", "slices"), "Paraboloid": ("radius", "height", "shape", "solid"),
    "Disc": ("radius", "slices"), "Box": ("size",), "Frustum": ("radius", "height", "taper", "solid"),
    "Translated": ("translation", "geometry"), "Scaled": ("scale", "geometry"),
    "AxisRotated": ("axis", "angle", "geometry"), "Shape": ("geometry", "appearance"),
}
GEOMETRY = {name: type(name, (Geometry,), {"PARAMETERS": SHAPE_PARAMETERS.get(name, ())})
            for name in GEOMETRY_NAMES}

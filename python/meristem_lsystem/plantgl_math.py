"""PlantGL's vectors and colours (`openalea.plantgl.math` and the `Color3` of `.all`), in Python.

The names and behaviour models use: `Vector2/3/4` with arithmetic, `*` as dot product between
vectors, `^` as cross product, `norm`, `normalize` (in place, returns the old norm), `normed`,
indexing and `x/y/z/w`; the free functions `norm`, `normalize`, `cross`, `dot`, `angle`,
`direction`. A vector is written in the result's lstring as its numbers."""

from __future__ import annotations

import math


class _Vector:
    __slots__ = ("_c",)
    SIZE = 3
    NAMES = "xyzw"

    def __init__(self, *args):
        if len(args) == 1 and not isinstance(args[0], (int, float)):
            args = tuple(args[0])
        values = [float(a) for a in args]
        if len(values) < self.SIZE:
            values += [0.0] * (self.SIZE - len(values))
        object.__setattr__(self, "_c", values[: self.SIZE])

    def __getattr__(self, attr):
        i = type(self).NAMES.find(attr)
        if len(attr) == 1 and 0 <= i < self.SIZE:
            return self._c[i]
        raise AttributeError(attr)

    def __setattr__(self, attr, value):
        i = type(self).NAMES.find(attr)
        if len(attr) == 1 and 0 <= i < self.SIZE:
            self._c[i] = float(value)
        else:
            raise AttributeError(attr)

    def __meristem_numbers__(self):
        return list(self._c)

    def _new(self, values):
        return type(self)(*values)

    def __len__(self):
        return self.SIZE

    def __getitem__(self, i):
        return self._c[i]

    def __setitem__(self, i, v):
        self._c[i] = float(v)

    def __iter__(self):
        return iter(self._c)

    def __add__(self, o):
        return self._new([a + b for a, b in zip(self._c, o)])

    __radd__ = __add__

    def __sub__(self, o):
        return self._new([a - b for a, b in zip(self._c, o)])

    def __rsub__(self, o):
        return self._new([b - a for a, b in zip(self._c, o)])

    def __neg__(self):
        return self._new([-a for a in self._c])

    def __pos__(self):
        return self._new(self._c)

    def __mul__(self, o):
        if isinstance(o, _Vector):
            return sum(a * b for a, b in zip(self._c, o._c))
        return self._new([a * o for a in self._c])

    def __rmul__(self, o):
        return self._new([a * o for a in self._c])

    def __truediv__(self, o):
        return self._new([a / o for a in self._c])

    __div__ = __truediv__

    def __xor__(self, o):
        return cross(self, o)

    def __eq__(self, o):
        try:
            return list(self._c) == [float(x) for x in o]
        except TypeError:
            return False

    def __hash__(self):
        return hash(tuple(self._c))

    def __abs__(self):
        return self._new([abs(a) for a in self._c])

    def __repr__(self):
        return f"{type(self).__name__}({','.join(repr(a) for a in self._c)})"

    def __copy__(self):
        return self._new(self._c)

    def __deepcopy__(self, memo):
        return self._new(self._c)

    def __getstate__(self):
        return self._c

    def __setstate__(self, state):
        object.__setattr__(self, "_c", list(state))

    def __reduce__(self):
        return (type(self), tuple(self._c))

    def __norm__(self):
        return math.sqrt(sum(a * a for a in self._c))

    def norm(self):
        return self.__norm__()

    def __len_sq(self):
        return sum(a * a for a in self._c)

    def normSquared(self):
        return self.__len_sq()

    def normalize(self):
        n = self.__norm__()
        if n > 0:
            object.__setattr__(self, "_c", [a / n for a in self._c])
        return n

    def normed(self):
        n = self.__norm__()
        return self._new([a / n for a in self._c]) if n > 0 else self._new(self._c)

    def __round__(self, nd=None):
        return self._new([round(a, nd or 0) for a in self._c])

    def anOrthogonalVector(self):
        x, y, z = (list(self._c) + [0.0, 0.0])[:3]
        if abs(x) > 1e-9 or abs(y) > 1e-9:
            return Vector3(-y, x, 0.0).normed()
        return Vector3(0.0, -z, y).normed()

    def anorm(self):
        return sum(abs(a) for a in self._c)

    def inorm(self):
        return max(abs(a) for a in self._c)

    def copy(self):
        return self._new(self._c)


class Vector2(_Vector):
    __slots__ = ()
    SIZE = 2


class Vector3(_Vector):
    __slots__ = ()
    SIZE = 3

    @staticmethod
    def Spherical(radius, theta, phi):
        return Vector3(radius * math.cos(theta) * math.sin(phi),
                       radius * math.sin(theta) * math.sin(phi), radius * math.cos(phi))

    @staticmethod
    def Cylindrical(radius, theta, z):
        return Vector3(radius * math.cos(theta), radius * math.sin(theta), z)


class Vector4(_Vector):
    __slots__ = ()
    SIZE = 4

    def project(self):
        w = self._c[3] or 1.0
        return Vector3(self._c[0] / w, self._c[1] / w, self._c[2] / w)


Vector3.ORIGIN = Vector3(0, 0, 0)
Vector3.OX, Vector3.OY, Vector3.OZ = Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1)
Vector2.ORIGIN, Vector2.OX, Vector2.OY = Vector2(0, 0), Vector2(1, 0), Vector2(0, 1)


def norm(v):
    return math.sqrt(sum(float(a) * float(a) for a in v))


def normalize(v):
    return v.normalize() if isinstance(v, _Vector) else norm(v)


def cross(a, b):
    a3, b3 = list(a) + [0.0] * (3 - len(a)), list(b) + [0.0] * (3 - len(b))
    c = (a3[1] * b3[2] - a3[2] * b3[1], a3[2] * b3[0] - a3[0] * b3[2], a3[0] * b3[1] - a3[1] * b3[0])
    if len(a) == 2 and len(b) == 2:
        return c[2]
    return Vector3(*c)


def dot(a, b):
    return sum(float(x) * float(y) for x, y in zip(a, b))


def angle(a, b, axis=None):
    na, nb = norm(a), norm(b)
    if na == 0 or nb == 0:
        return 0.0
    c = max(-1.0, min(1.0, dot(a, b) / (na * nb)))
    result = math.acos(c)
    if axis is not None and dot(cross(a, b), axis) < 0:
        result = -result
    return result


def direction(v):
    n = norm(v)
    return type(v)(*[a / n for a in v]) if isinstance(v, _Vector) and n else v


class Color3:
    """An RGB colour, 0-255 integers."""

    def __init__(self, r=0, g=0, b=0, *rest):
        if not isinstance(r, (int, float)):
            r, g, b = list(r)[:3]
        self.red, self.green, self.blue = int(r), int(g), int(b)

    def __iter__(self):
        return iter((self.red, self.green, self.blue))

    def __getitem__(self, i):
        return (self.red, self.green, self.blue)[i]

    def __mul__(self, k):
        return Color3(*(min(255, max(0, int(c * k))) for c in self))

    __rmul__ = __mul__

    def __add__(self, o):
        return Color3(*(min(255, a + b) for a, b in zip(self, o)))

    def __eq__(self, o):
        return isinstance(o, Color3) and tuple(self) == tuple(o)

    def __hash__(self):
        return hash(tuple(self))

    def __meristem_numbers__(self):
        return list(self)

    def clampedRed(self):
        return self.red / 255

    def clampedGreen(self):
        return self.green / 255

    def clampedBlue(self):
        return self.blue / 255

    def __repr__(self):
        return f"Color3({self.red},{self.green},{self.blue})"


class Color4(Color3):
    def __init__(self, r=0, g=0, b=0, a=0):
        if not isinstance(r, (int, float)):
            vals = list(r) + [0]
            r, g, b, a = vals[:4]
        super().__init__(r, g, b)
        self.alpha = int(a)

    def __meristem_numbers__(self):
        return [self.red, self.green, self.blue, self.alpha]


for _c in (Color3,):
    _c.BLACK, _c.WHITE = Color3(0, 0, 0), Color3(255, 255, 255)
    _c.RED, _c.GREEN, _c.BLUE = Color3(255, 0, 0), Color3(0, 255, 0), Color3(0, 0, 255)
    _c.YELLOW, _c.CYAN, _c.MAGENTA = Color3(255, 255, 0), Color3(0, 255, 255), Color3(255, 0, 255)


class Matrix3:
    """A 3 × 3 matrix (rows): `Matrix3.axisRotation(axis, angle)`, `m * v`, `m * m`."""

    def __init__(self, *values):
        if len(values) == 9:
            self.rows = [[float(x) for x in values[i : i + 3]] for i in (0, 3, 6)]
        elif len(values) == 3:
            # PlantGL builds a matrix from three column vectors
            cols = [list(v) for v in values]
            self.rows = [[float(cols[c][r]) for c in range(3)] for r in range(3)]
        else:
            self.rows = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]

    @staticmethod
    def axisRotation(axis, angle):
        x, y, z = (float(a) for a in axis)
        n = math.sqrt(x * x + y * y + z * z) or 1.0
        x, y, z = x / n, y / n, z / n
        c, s, t = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
        return Matrix3(t * x * x + c, t * x * y - s * z, t * x * z + s * y,
                       t * x * y + s * z, t * y * y + c, t * y * z - s * x,
                       t * x * z - s * y, t * y * z + s * x, t * z * z + c)

    def __mul__(self, o):
        if isinstance(o, Matrix3):
            cols = list(zip(*o.rows))
            return Matrix3(*[sum(a * b for a, b in zip(row, col)) for row in self.rows for col in cols])
        if isinstance(o, (int, float)):
            return Matrix3(*[a * o for row in self.rows for a in row])
        v = list(o)
        return Vector3(*[sum(a * b for a, b in zip(row, v)) for row in self.rows])

    def transpose(self):
        return Matrix3(*[self.rows[c][r] for r in range(3) for c in range(3)])

    def getColumn(self, i):
        return Vector3(*[row[i] for row in self.rows])

    def getRow(self, i):
        return Vector3(*self.rows[i])


Matrix3.IDENTITY = Matrix3()

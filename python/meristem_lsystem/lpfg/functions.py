"""lpfg's function files: `func(NAME, x)` reads a function of the object's `.fset` or `.func`
files, `tfunc(NAME, t)` a timeline function (`.tset`), `val(NAME)` a value (`.vset`).

lpfg numbers them in one list from 1 (the `.fset`, the `.tset`, the `.vset`, then the `.func`
files) and defines each name as its number. A function is a clamped uniform cubic B-spline
through its control points (cpfg's `SplineFunction`), which lpfg reads through `samples`
values (10 to 1,000) joined by straight lines.
"""

import re


def _bspline_point(points, d):
    n = len(points) - 1
    if d >= 1.0:
        return points[n]
    u = max(d, 0.0) * (n - 2.0)

    def knot(j):
        if j < 4:
            return 0.0
        if j > n:
            return n - 2.0
        return j - 3.0

    basis = [1.0 if knot(k) <= u < knot(k + 1) else 0.0 for k in range(n + 4)]
    for order in range(2, 5):
        for k in range(n + 4 - order + 1):
            s = 0.0
            div = knot(k + order - 1) - knot(k)
            if div != 0.0:
                s = (u - knot(k)) / div * basis[k]
            div = knot(k + order) - knot(k + 1)
            if div != 0.0:
                s += (knot(k + order) - u) / div * basis[k + 1]
            basis[k] = s
    return (sum(p[0] * b for p, b in zip(points, basis)), sum(p[1] * b for p, b in zip(points, basis)))


def _spline_value(points, x):
    first, last = _bspline_point(points, 0.0)[0], _bspline_point(points, 1.0)[0]
    target = min(max(x, min(first, last)), max(first, last))
    low, high = 0.0, 1.0
    at = _bspline_point(points, 0.5)
    for _ in range(50):
        middle = (low + high) / 2
        at = _bspline_point(points, middle)
        if at[0] > target:
            high = middle
        else:
            low = middle
    return at[1]


class Curve:
    def __init__(self, name, points, samples):
        self.name = name
        samples = min(max(samples, 10), 1000)
        if len(points) < 4:
            points = points + [points[-1]] * (4 - len(points)) if points else [(0.0, 0.0)] * 4
        self.table = [(i / (samples - 1), _spline_value(points, i / (samples - 1))) for i in range(samples)]

    def value(self, x):
        t = self.table
        if x != x or x <= t[0][0]:
            return t[0][1]
        if x >= t[-1][0]:
            return t[-1][1]
        step = t[1][0] - t[0][0]
        k = min(int((x - t[0][0]) / step), len(t) - 2)
        (x0, y0), (x1, y1) = t[k], t[k + 1]
        return y0 + (y1 - y0) * (x - x0) / (x1 - x0)


def _read_function(text, default_name):
    name, samples, points, reading = default_name, 100, [], False
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("name:"):
            name = line[5:].strip()
        elif line.startswith("samples:"):
            try:
                samples = int(line[8:].strip())
            except ValueError:
                pass
        elif line.startswith("points:"):
            reading = True
        elif reading:
            values = []
            for w in line.split():
                try:
                    values.append(float(w))
                except ValueError:
                    break
            if len(values) >= 2:
                times = int(values[2]) if len(values) > 2 else 1
                points.extend([(values[0], values[1])] * max(1, min(times, 16)))
    return Curve(name, points, samples)


class FunctionSet:
    def __init__(self, files, notes):
        self.entries = []  # Curve, ('timeline', curve, start, end) or ('value', v)
        self.names = {}
        for name in sorted(n for n in files if n.endswith(".fset")):
            for chunk in re.split(r"(?m)^(?=fver)", files[name])[1:]:
                self._add(_read_function(chunk, name))
        for name in sorted(n for n in files if n.endswith(".tset")):
            notes.append({"line": 0, "message": f"{name}: timeline functions are read as plain functions of 0…1"})
            for chunk in re.split(r"(?m)^(?=fver)", files[name])[1:]:
                self._add(_read_function(chunk, name))
        for name in sorted(n for n in files if n.endswith(".vset")):
            for m in re.finditer(r"(?m)^\s*#define\s+(\w+)\s+(\S+)", files[name]):
                try:
                    self.names[m.group(1)] = len(self.entries) + 1
                    self.entries.append(float(m.group(2)))
                except ValueError:
                    pass
        for name in sorted(n for n in files if n.endswith(".func")):
            self._add(_read_function(files[name], name[:-5]))

    def _add(self, curve):
        self.entries.append(curve)
        self.names[curve.name] = len(self.entries)

    def _entry(self, k):
        k = int(k)
        if not 1 <= k <= len(self.entries):
            from .lexer import LpfgError
            raise LpfgError(f"func: there is no function number {k} among the object's function files")
        return self.entries[k - 1]

    def value(self, k, x):
        e = self._entry(k)
        return e.value(float(x)) if isinstance(e, Curve) else float(e)

    def timeline(self, k, t):
        return self.value(k, t)

    def val(self, k):
        e = self._entry(k)
        return float(e) if not isinstance(e, Curve) else e.value(0.0)

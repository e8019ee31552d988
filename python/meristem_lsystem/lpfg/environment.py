"""lpfg's environmental programs, run in Python between steps. One is here: vlab's `honda81`
(`ENVIRO/honda81/honda81.c`, Honda 1981's collision test), which 12 of the course objects use:
every `E1`/`E2` query is stored with the turtle's position and its first parameter (vigor); a
query replies 1, or 0 when another query of the same kind (E1 with E1) with at least its vigor
lies within `radius` (in 3D, or in the plane when `3d case: off`). The object names the program
in its communication file (`.e`: `executable: honda81 -e commfile.e density.spec`).
"""

import math


def environment_of(files, notes):
    """The object's environment (a Honda81), or None; a note for a program not reproduced."""
    for name in sorted(files):
        if not name.endswith(".e"):
            continue
        lines = files[name].splitlines()
        words = lines[0].split() if lines else []
        if len(words) < 2 or words[0] != "executable:":
            continue
        program = words[1].split("/")[-1]
        if program != "honda81":
            notes.append({"line": 0, "message": f"{name} runs the environmental program {program}, "
                          "which is not reproduced: the query modules keep their parameters"})
            return None
        spec = words[-1]
        if spec not in files:
            notes.append({"line": 0, "message": f"{name} runs honda81 with {spec}, which is not among the "
                          "object's files: its radius is 0 (only queries at the same point meet)"})
        return Honda81(files.get(spec, ""))
    return None


class Honda81:
    def __init__(self, spec):
        self.radius = 0.0
        self.is3d = False
        for line in spec.splitlines():
            key, _, value = line.partition(":")
            key, value = key.strip().lower(), value.replace(",", " ").split()
            if key == "radius" and value:
                try:
                    self.radius = float(value[0])
                except ValueError:
                    pass
            elif key == "3d case" and value:
                self.is3d = value[0] == "on"

    def answer(self, queries):
        """`queries`: [(kind, vigor, position)]; the replies, 1 or 0, in order."""
        r2 = self.radius * self.radius
        cell = max(self.radius, 1e-9)
        grid = {}
        for k, (kind, _, p) in enumerate(queries):
            key = (kind,) + tuple(math.floor(v / cell) for v in p[: 3 if self.is3d else 2])
            grid.setdefault(key, []).append(k)
        replies = []
        for i, (kind, vigor, p) in enumerate(queries):
            reply = 1
            base = [math.floor(v / cell) for v in p[: 3 if self.is3d else 2]]
            for offset in _OFFSETS[len(base)]:
                key = (kind,) + tuple(b + o for b, o in zip(base, offset))
                for j in grid.get(key, ()):
                    if j == i or vigor > queries[j][1]:
                        continue
                    q = queries[j][2]
                    d2 = (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2
                    if self.is3d:
                        d2 += (p[2] - q[2]) ** 2
                    if d2 <= r2:
                        reply = 0
                        break
                if reply == 0:
                    break
            replies.append(reply)
        return replies


def _offsets(n):
    if n == 0:
        return [()]
    return [(o,) + rest for o in (-1, 0, 1) for rest in _offsets(n - 1)]


_OFFSETS = {2: _offsets(2), 3: _offsets(3)}  # the neighbouring cells of a grid cell

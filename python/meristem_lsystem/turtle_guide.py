"""PlantGL's turtle guides, written out as the turns they make: `SetGuide`, `EndGuide`, `nF`
and `Sweep` in the final string become `F`/`f` and `&`/`+` that Meristem's turtle draws.

Ported from PlantGL (openalea/plantgl, CeCILL-C): `Turtle::_applyGuide` and `_ajustToGuide`,
`Turtle::nF` and `Turtle::sweep` in `src/cpp/plantgl/algo/modelling/turtle.cpp`, and
`Turtle2DPath` in `turtlepath.cpp`. A 2D guide (a `Curve2D` and the length it maps to) makes
each `F(l)`/`f(l)` (l > 0) first turn the turtle from the curve's last direction to the chord
toward the point at arc length l further on, move by that chord's length times the guide's
scale (length / curve length), then turn to the curve's tangent there. The turn is about the
turtle's current left axis (PlantGL: `axisRotation(left, -deviation)`, which is `&(-deviation)`)
or, for `SetGuide(curve, length, True)` (y orientation), about its up axis (`+(deviation)`).
Both are relative turns, so writing them as modules is exact whatever else turns the turtle.
The guide ends once its length is used; `[` and `]` save and restore it as PlantGL's turtle
stack copies it. `nF(length, dl[, radius, radiusvariation])` is PlantGL's series of `F(dl)`
with interpolated widths; `Sweep(path, section, length, dl[, radius, variation])` is
`SetGuide(path, length) SetContour(section) nF(length, dl, radius, variation)`.
A 3D guide (`SetGuide` with a 3D curve) and `PositionOnGuide` are left in the string with a
note (Meristem's turtle ignores them)."""

from __future__ import annotations

import math

from .lstring import Module
from .plantgl_math import Vector2

BRACKETS = {"[": "[", "SB": "[", "]": "]", "EB": "]"}
WIDTH_SET = {"SetWidth"}
WIDTH_STEP = {"_", "IncWidth", "!", "DecWidth"}
DEFAULT_WIDTH = 0.1  # PlantGL TurtleParam: width(0.1)
EPSILON = 1e-5  # PlantGL: GEOM_EPSILON


def _angle(a: Vector2, b: Vector2) -> float:
    """PlantGL's signed angle from a to b (atan2 of cross and dot)."""
    return math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1])


class Guide2D:
    """PlantGL's Turtle2DPath: where on the curve the turtle is, and its last direction."""

    def __init__(self, curve, length, yorientation=False, ccw=False):
        self.curve = curve
        self.total = float(length)
        self.actual = curve.getLength()
        if not self.actual:
            raise ValueError("SetGuide: the guide curve has no length")
        self.scale = self.total / self.actual
        self.mapping = curve.getArcLengthToUMapping()
        self.orientation, self.ccw = bool(yorientation), bool(ccw)
        heading = (0.0, 1.0) if self.orientation else (1.0, 0.0)
        if self.ccw:
            heading = (0.0, -1.0) if self.orientation else (-1.0, 0.0)
        self.last_heading = Vector2(*heading)
        self.last_position = curve.getPointAt(curve.firstKnot)
        self.t = 0.0

    def copy(self) -> "Guide2D":
        other = object.__new__(Guide2D)
        other.__dict__.update(self.__dict__)
        return other

    def _turn(self, tangent) -> Module | None:
        deviation = _angle(self.last_heading, tangent)
        if self.ccw:
            deviation = -deviation
        self.last_heading = tangent
        if abs(deviation) < 1e-12:
            return None
        if self.orientation:
            return Module("+", [math.degrees(deviation)])
        return Module("&", [-math.degrees(deviation)])

    def advance(self, length: float) -> tuple[list[Module], float]:
        """`_applyGuide(l)` for l > 0: the turn before the move and the length moved."""
        dt = length / self.total
        nxt = self.t + dt
        reminder = nxt - 1.0
        if reminder > EPSILON:
            nxt = 1.0
        next_u = self.mapping(nxt)
        next_pos = self.curve.getPointAt(next_u)
        target = next_pos
        if reminder > EPSILON:
            end_tangent = self.curve.getTangentAt(next_u).normed()
            target = next_pos + end_tangent * (reminder * self.actual)
        tangent = target - self.last_position
        chord = tangent.norm()
        tangent = tangent.normed()
        self.t = nxt
        self.last_position = next_pos
        turn = self._turn(tangent)
        return ([turn] if turn else []), chord * self.scale

    def adjust(self) -> list[Module]:
        """`_ajustToGuide`: turn to the curve's tangent where the turtle now is."""
        turn = self._turn(self.curve.getTangentAt(self.mapping(self.t)))
        return [turn] if turn else []


def _number(value, default=None):
    return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else default


def _nf(args, width) -> tuple[list[Module], float | None]:
    """PlantGL's `Turtle::nF`: the F modules and the width after them."""
    length, dl = float(args[0]), float(args[1])
    steps = int(length / dl) if dl > 0 else 0
    delta = length - steps * dl
    out: list[Module] = []
    if len(args) < 3:
        out = [Module("F", [dl]) for _ in range(steps)]
        if delta > EPSILON:
            out.append(Module("F", [delta]))
        return out, width
    radius = float(args[2])
    variation = args[3] if len(args) > 3 else None
    if variation is not None:
        fx, lx = variation.firstx, variation.lastx
        du = (dl / length) * (lx - fx)
        u = fx
        out.append(Module("SetWidth", [variation(u) * radius]))
        for _ in range(steps):
            u += du
            out.append(Module("F", [dl, variation(u) * radius]))
        last = variation(u) * radius
        if delta > EPSILON:
            last = radius * variation(lx)
            out.append(Module("F", [delta, last]))
        return out, last
    if width is None:
        raise ValueError("nF with a radius after a width step (_ or ! without a value): the width "
                         "it starts from is not known")
    cw, dw = width, (radius - width) / length
    for _ in range(steps):
        cw += dw * dl
        out.append(Module("F", [dl, cw]))
    if delta > EPSILON:
        out.append(Module("F", [delta, radius]))
        cw = radius
    return out, cw


class _State:
    def __init__(self, guide=None, width=DEFAULT_WIDTH):
        self.guide, self.width = guide, width

    def copy(self) -> "_State":
        return _State(self.guide.copy() if self.guide else None, self.width)


def _is_2d(curve) -> bool:
    return getattr(curve, "DIM", None) == 2 and hasattr(curve, "getArcLengthToUMapping")


def _move(state: _State, m: Module, out: list) -> None:
    """F or f under the state's guide (or as it is without one)."""
    length = _number(m.args[0] if m.args else 1.0, 0.0)
    g = state.guide
    if g is None or length <= 0:
        out.append(m)
    elif g.t >= 1.0:
        state.guide = None  # PlantGL: the guide is used up
        out.append(m)
    else:
        turns, moved = g.advance(length)
        out.extend(turns)
        out.append(Module(m.name, [moved, *m.args[1:]]))
        out.extend(g.adjust())
    if m.name == "F" and len(m.args) > 1 and _number(m.args[1], -1.0) > -EPSILON:
        state.width = float(m.args[1])


def _set_guide(state: _State, m: Module, out: list, note) -> None:
    curve = m.args[0] if m.args else None
    if not _is_2d(curve):
        note(f"{m.name} with a {type(curve).__name__} (a 3D guide) is not reproduced: Meristem's turtle "
             "ignores it")
        out.append(m)
        return
    state.guide = Guide2D(curve, *m.args[1:4])


def expand_guides(modules, note) -> list:
    """The string with guides, `nF` and `Sweep` written as moves and turns (see the module doc).
    `note(message)` records what is left as it was."""
    stack: list[_State] = []
    state = _State()
    out: list = []
    for m in modules:
        name = getattr(m, "name", None)
        if BRACKETS.get(name) == "[":
            stack.append(state.copy())
            out.append(m)
        elif BRACKETS.get(name) == "]":
            state = stack.pop() if stack else _State()
            out.append(m)
        elif name in ("F", "f"):
            _move(state, m, out)
        elif name == "SetGuide":
            _set_guide(state, m, out, note)
        elif name == "EndGuide":
            state.guide = None
        elif name in ("nF", "Sweep"):
            args = list(m.args)
            if name == "Sweep":
                _set_guide(state, Module("SetGuide", [args[0], args[2]]), out, note)
                out.append(Module("SetContour", [args[1]]))
                args = [args[2], args[3], args[4] if len(args) > 4 else 1.0, *args[5:6]]
            moves, state.width = _nf(args, state.width)
            for move in moves:
                if move.name == "SetWidth":
                    out.append(move)
                else:
                    _move(state, move, out)
        elif name in WIDTH_SET or (name in WIDTH_STEP and m.args):
            state.width = _number(m.args[0] if m.args else None, state.width)
            out.append(m)
        elif name in WIDTH_STEP:
            state.width = None
            out.append(m)
        else:
            if name == "PositionOnGuide":
                note("PositionOnGuide is not reproduced: Meristem's turtle ignores it")
            out.append(m)
    return out

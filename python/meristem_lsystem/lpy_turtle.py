"""PlantGL's turtle for position and frame, as L-Py runs it to fill its query modules.

L-Py (lsystem.cpp, `Lsystem::__step`) interprets the string with its `envturtle` before every
production step whose rules hold a query module (`?P`/GetPos, `?H`/GetHead, `?U`/GetUp,
`?L`/GetLeft, `?R`/GetRight, `?F`/GetFrame) in a predecessor or a context: the axiom before
step 0, then each step's string before the next. The interpretation rules (homomorphism) apply
up to their maximum depth; a module no rule rewrites is interpreted itself, and a query there
receives the turtle's values (`ParamModule::_setValues`: 3 parameters x, y, z; 2 → x, y; 1 →
the number, or the items of a vector/list; none → one Vector3; `?F` → p, h, u, l). Queries that
interpretation rules produce are filled and dropped with their production, as in L-Py.
Decomposition steps fill nothing (L-Py's `__recursiveSteps` takes no query flag).

Ported from PlantGL (openalea/plantgl, CeCILL-C), `src/cpp/plantgl/algo/modelling/turtle.cpp`
and `turtleparam.cpp`, and L-Py's `predefinedmodules.cpp` for the parameters each module takes:
the frame starts at H = (0,0,1), L = (0,-1,0), U = (1,0,0); `+ - ^ & / \\` turn by their angle or
the angle increment (60° unless the model sets it), `|` turns 180° about U; `F f` (and `@B`,
`@b`) move by their length or the default step, times the scale's z, after the guide's turn and
tropism (`@Tp`, `@Ts`: `_tendTo(tropism, elasticity)`); `nF`, `Sweep` and 2D guides (`SetGuide`,
`EndGuide`) as PlantGL's `nF` and `_applyGuide` (through `turtle_guide.Guide2D`); `[ ]` save and
restore the whole state; `@M`/MoveTo, MoveRel, LineTo, OLineTo, LineRel, OLineRel, Pinpoint,
PinpointRel, `@R`/SetHead, EulerAngles, `@v`/RollToVert, `@h`/RollToHorizontal, `@D @Di @Dd`,
the reflections. Widths, colours and shapes do not move the turtle and are skipped. Not
reproduced (said in a note): 3D guides, PositionOnGuide, screen projection (`@2D`), and the
model's `StartInterpretation`/`EndInterpretation` functions."""

from __future__ import annotations

import math

from .lstring import Module, predefined_names
from .plantgl_math import Vector3, _Vector

EPS = 1e-5  # PlantGL's GEOM_EPSILON
QUERIES = {"?P", "?H", "?U", "?L", "?R", "?F"}
UNREPRODUCED = {"@2D": "screen projection (@2D)", "PositionOnGuide": "PositionOnGuide"}


def _add(a, b, k=1.0):
    return (a[0] + b[0] * k, a[1] + b[1] * k, a[2] + b[2] * k)


def _scale(a, k):
    return (a[0] * k, a[1] * k, a[2] * k)


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _norm(a):
    return math.sqrt(_dot(a, a))


def _normed(a):
    n = _norm(a)
    return (_scale(a, 1.0 / n), n) if n > 0 else (a, 0.0)


def _rotation(axis, angle):
    """PlantGL's Matrix3::axisRotation (radians, right-handed), as rows."""
    (x, y, z), n = _normed(axis)
    if n == 0:
        return ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    c, s = math.cos(angle), math.sin(angle)
    t = 1 - c
    return ((t * x * x + c, t * x * y - s * z, t * x * z + s * y),
            (t * x * y + s * z, t * y * y + c, t * y * z - s * x),
            (t * x * z - s * y, t * y * z + s * x, t * z * z + c))


def _apply(m, v):
    return (_dot(m[0], v), _dot(m[1], v), _dot(m[2], v))


def _signed_angle(a, b, axis):
    """PlantGL's angle(a, b, axis): the angle from a to b, negative when a×b opposes axis."""
    na, nb = _norm(a), _norm(b)
    if na == 0 or nb == 0:
        return 0.0
    result = math.acos(max(-1.0, min(1.0, _dot(a, b) / (na * nb))))
    return -result if _dot(_cross(a, b), axis) < 0 else result


def _real(value, default=0.0):
    if isinstance(value, bool):
        return float(value)
    if isinstance(value, (int, float)):
        return float(value)
    try:
        return float(value)
    except (TypeError, ValueError):
        return default


def _vector(value):
    """A Vector3 parameter (PlantGL's bp::extract<Vector3>): a vector or a 3-sequence."""
    if isinstance(value, _Vector) and len(value) == 3:
        return tuple(float(a) for a in value)
    if isinstance(value, (tuple, list)) and len(value) == 3 and all(isinstance(a, (int, float)) for a in value):
        return tuple(float(a) for a in value)
    return None


def _point(args):
    """`x, y, z` or `v` (missing coordinates 0), as L-Py reads LineTo, Pinpoint …"""
    if not args:
        return None
    v = _vector(args[0])
    if v is not None:
        return v
    xs = [_real(a) for a in args[:3]]
    return tuple(xs + [0.0] * (3 - len(xs)))


class State:
    __slots__ = ("p", "h", "l", "u", "scale", "tropism", "elasticity", "guide", "reflection")

    def __init__(self):
        self.p, self.h, self.l, self.u = (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0), (1.0, 0.0, 0.0)
        self.scale, self.tropism, self.elasticity = (1.0, 1.0, 1.0), (0.0, 0.0, 1.0), 0.0
        self.guide, self.reflection = None, [1.0, 1.0, 1.0]

    def copy(self):
        other = State()
        for k in State.__slots__:
            setattr(other, k, getattr(self, k))
        other.guide = self.guide.copy() if self.guide is not None else None
        other.reflection = list(self.reflection)
        return other


class LpyTurtle:
    """Position and frame of PlantGL's turtle through a string of L-Py modules."""

    def __init__(self, settings=None, note=None):
        settings = settings or {}
        self.angle = float(settings.get("angle_increment", 60.0))
        self.step = float(settings.get("default_step", 1.0))
        self.multiplier = float(settings.get("scale_multiplier", 0.5))
        self.note = note or (lambda message: None)
        self.s = State()
        self.stack: list[State] = []
        self.names = predefined_names()

    # ----- the frame -----
    def transform(self, m):
        s = self.s
        s.h, s.l, s.u = _apply(m, s.h), _apply(m, s.l), _apply(m, s.u)

    def left(self, a):
        m = _rotation(self.s.u, math.radians(a) * self.s.reflection[1])
        self.s.h, self.s.l = _apply(m, self.s.h), _apply(m, self.s.l)

    def down(self, a):
        m = _rotation(self.s.l, math.radians(a))
        k = self.s.reflection[2]
        self.s.h, self.s.u = _scale(_apply(m, self.s.h), k), _scale(_apply(m, self.s.u), k)

    def roll_left(self, a):
        m = _rotation(self.s.h, math.radians(a))
        k = self.s.reflection[0]
        self.s.u, self.s.l = _scale(_apply(m, self.s.u), k), _scale(_apply(m, self.s.l), k)

    def tend_to(self, t, strength=1.0):
        """PlantGL's `_tendTo`: turn the frame towards t by `strength` of the angle."""
        h = self.s.h
        cp = _cross(h, t)
        sinus = _norm(cp)
        cosinus = _dot(h, t)
        if sinus > EPS:
            self.transform(_rotation(_scale(cp, 1.0 / sinus), math.atan2(sinus, cosinus) * strength))
        elif cosinus < EPS:
            self.transform(_rotation(self.s.u, math.pi * strength))

    def set_head(self, h, u):
        h, lh = _normed(h)
        u, lu = _normed(u)
        if lh < EPS or lu < EPS:
            return
        left = _cross(u, h)
        if _norm(left) < EPS:
            return
        if abs(_dot(h, u)) > EPS:
            u = _cross(h, left)
        self.s.h, self.s.u, self.s.l = h, u, left

    def euler(self, azimuth=180.0, elevation=90.0, roll=0.0):
        x, y, z = math.radians(azimuth), -math.radians(elevation), math.radians(roll)
        cz, sz, cy, sy, cx, sx = math.cos(z), math.sin(z), math.cos(y), math.sin(y), math.cos(x), math.sin(x)
        m = ((cx * cy, cx * sy * sz - sx * cz, cx * sy * cz + sx * sz),
             (sx * cy, cx * cz + sx * sy * sz, sx * sy * cz - cx * sz),
             (-sy, cy * sz, cy * cz))
        self.s.h, self.s.u = _apply(m, (1.0, 0.0, 0.0)), _apply(m, (0.0, 0.0, 1.0))
        self.s.l = _cross(self.s.u, self.s.h)

    def roll_to_vert(self, alpha=1.0, top=(0.0, 0.0, 1.0)):
        s = self.s
        if alpha <= 0.0:
            return
        if alpha >= 1.0:
            left, n = _normed(_cross(top, s.h))
            s.l = (0.0, -1.0, 0.0) if n < EPS else left
            s.u = _cross(s.h, s.l)
            return
        nleft, _ = _normed(_cross(top, s.h))
        self.roll_left(-math.degrees(_signed_angle(s.l, nleft, s.h)) * alpha)

    def roll_to_horizontal(self, alpha=1.0, top=(0.0, 0.0, 1.0)):
        s = self.s
        if alpha <= 0.0:
            return
        alpha = min(alpha, 1.0)
        off = _dot(s.h, top)
        if abs(off) > EPS:
            target, n = _normed(_add(s.h, top, -off))
            if n < EPS:
                target = (1.0, 0.0, 0.0)
            axis, _ = _normed(_cross(s.h, target))
            self.transform(_rotation(axis, _signed_angle(s.h, target, axis) * alpha))

    # ----- moves -----
    def _guided(self, length):
        """PlantGL's `_applyGuide(l)` for l > 0: the guide's turn; the length to move."""
        g = self.s.guide
        if g is None:
            return length
        if g.t >= 1.0:
            self.s.guide = None  # used up
            return length
        turns, moved = g.advance(length)
        for turn in turns:
            self.command(turn)
        return moved

    def _adjust(self):
        g = self.s.guide
        if g is not None:
            for turn in g.adjust():
                self.command(turn)

    def forward(self, length, draws=True):
        """F (draws) or f: guide, tropism, move, guide adjustment; a negative F turns around."""
        if draws and length < -EPS:
            self.left(180.0)
            self.forward(-length)
            self.left(180.0)
            return
        if length <= 0 and draws:
            return
        guided = length > 0 and self.s.guide is not None
        if guided:
            length = self._guided(length)
        if self.s.elasticity > EPS:
            self.tend_to(self.s.tropism, self.s.elasticity)
        if not draws or length > EPS:
            self.s.p = _add(self.s.p, self.s.h, length * self.s.scale[2])
        if guided:
            self._adjust()

    def line_to(self, target, oriented):
        saved = (self.s.h, self.s.l, self.s.u)
        h, length = _normed(_add(target, self.s.p, -1.0))
        if length > EPS:
            self.tend_to(h)
            self.forward(length)
        if not oriented:
            self.s.h, self.s.l, self.s.u = saved

    def pinpoint(self, direction):
        h, length = _normed(direction)
        if length > EPS:
            self.tend_to(h)

    def n_f(self, length, dl):
        steps = int(length / dl) if dl > 0 else 0
        for _ in range(steps):
            self.forward(dl)
        delta = length - steps * dl
        if delta > EPS:
            self.forward(delta)

    def set_guide(self, args):
        from .turtle_guide import Guide2D, _is_2d

        curve = args[0] if args else None
        if _is_2d(curve):
            self.s.guide = Guide2D(curve, *args[1:4])
        else:
            self.note(f"a 3D guide ({type(curve).__name__}) is not followed by the turtle that fills "
                      "turtle queries: the values after it are those of a straight path")

    # ----- one module -----
    def command(self, m) -> None:
        name = self.names.get(m.name, m.name)
        handler = HANDLERS.get(name)
        if handler is not None:
            handler(self, list(m.args))
        elif name in UNREPRODUCED:
            self.note(f"{UNREPRODUCED[name]} is not reproduced by the turtle that fills turtle queries")

    def query(self, m) -> Module:
        """The query module `m` with the turtle's values (a new module)."""
        name = self.names.get(m.name, m.name)
        s = self.s
        args = list(m.args)
        if name == "?F":
            values = [Vector3(*v) for v in (s.p, s.h, s.u, s.l)]
            return Module(m.name, values + args[4:])
        value = {"?P": s.p, "?H": s.h, "?U": s.u, "?L": s.l, "?R": _scale(s.l, -1.0)}[name]
        if len(args) >= 2:
            args[: min(3, len(args))] = list(value[: min(3, len(args))])
        elif len(args) == 1:
            first = args[0]
            if isinstance(first, (int, float)):
                args[0] = value[0]
            else:
                try:
                    first = first.copy() if hasattr(first, "copy") else type(first)(first)
                    for k in range(min(3, len(first))):
                        first[k] = value[k]
                    args[0] = first
                except (TypeError, ValueError, AttributeError):
                    args[0] = value[0]
        else:
            args = [Vector3(*value)]
        return Module(m.name, args)


def _angle_of(t, args):
    return _real(args[0], t.angle) if args else t.angle


def _move_to(t, args):
    p = t.s.p
    if not args:
        t.s.p = (0.0, 0.0, 0.0)
        return
    v = _vector(args[0]) if len(args) == 1 else None
    if v is not None:
        t.s.p = v
        return
    coords = [p[k] if k >= len(args) or args[k] is None else _real(args[k]) for k in range(3)]
    t.s.p = tuple(coords)


def _set_head(t, args):
    if not args:
        t.set_head((0.0, 0.0, 1.0), (1.0, 0.0, 0.0))
        return
    first = _vector(args[0])
    if first is not None:
        h, u = first, (_vector(args[1]) if len(args) > 1 else None)
    else:
        xs = [_real(a) for a in args[:6]]
        h = tuple((xs[:3] + [0.0, 0.0, 0.0])[:3])
        u = tuple((xs[3:6] + [0.0, 0.0, 0.0])[:3]) if len(xs) > 3 else None
    h, n = _normed(h)
    if n < EPS:
        return
    if u is None or _norm(u) < EPS:
        t.pinpoint(h)
    else:
        t.set_head(h, u)


def _scale_by(t, args, mode):
    if mode == "set":
        k = _real(args[0], 1.0) if args else 1.0
        t.s.scale = (k, k, k)
        return
    k = _real(args[0], 1.0) if args else t.multiplier
    k = k if mode == "mult" else 1.0 / k if k else 1.0
    t.s.scale = _scale(t.s.scale, k)


def _tropism(t, args):
    if not args:
        v = (0.0, 0.0, 1.0)  # L-Py calls setTropism() without a value: PlantGL's default
    elif len(args) == 1:
        v = _vector(args[0]) or (_real(args[0]), 0.0, 1.0)
    elif len(args) == 2:
        first = args[0]
        v = (float(first[0]), float(first[1]), 0.0) if isinstance(first, _Vector) else (_real(args[0]), _real(args[1]), 1.0)
    else:
        v = (_real(args[0]), _real(args[1]), _real(args[2]))
    t.s.tropism = _normed(v)[0]


def _elasticity(t, args):
    value = _real(args[0]) if args else 0.0
    if 0.0 <= value <= 1.0:
        t.s.elasticity = value


def _push(t, args):
    t.stack.append(t.s.copy())


def _pop(t, args):
    if t.stack:
        t.s = t.stack.pop()


def _sweep(t, args):
    if len(args) >= 4:
        t.set_guide([args[0], args[2]])
        t.n_f(_real(args[2]), _real(args[3]))


def _reflect(k):
    def handler(t, args):
        t.s.reflection[k] = -t.s.reflection[k]
    return handler


HANDLERS = {
    "[": _push, "]": _pop,
    "F": lambda t, a: t.forward(_real(a[0], t.step) if a else t.step),
    "f": lambda t, a: t.forward(_real(a[0], t.step) if a else t.step, draws=False),
    "@B": lambda t, a: t.forward(_real(a[0], t.step) if a else t.step),
    "@b": lambda t, a: t.forward(_real(a[0], t.step) if a else t.step),
    "nF": lambda t, a: t.n_f(_real(a[0]), _real(a[1])) if len(a) >= 2 else None,
    "Sweep": _sweep,
    "SetGuide": lambda t, a: t.set_guide(a),
    "EndGuide": lambda t, a: setattr(t.s, "guide", None),
    "+": lambda t, a: t.left(_angle_of(t, a)),
    "-": lambda t, a: t.left(-_angle_of(t, a)),
    "&": lambda t, a: t.down(_angle_of(t, a)),
    "^": lambda t, a: t.down(-_angle_of(t, a)),
    "/": lambda t, a: t.roll_left(_angle_of(t, a)),
    "\\": lambda t, a: t.roll_left(-_angle_of(t, a)),
    "|": lambda t, a: t.left(180.0),
    "@M": _move_to,
    "MoveRel": lambda t, a: setattr(t.s, "p", _add(t.s.p, _point(a))) if a else None,
    "LineTo": lambda t, a: t.line_to(_point(a), False) if a else None,
    "OLineTo": lambda t, a: t.line_to(_point(a), True) if a else None,
    "LineRel": lambda t, a: t.line_to(_add(t.s.p, _point(a)), False) if a else None,
    "OLineRel": lambda t, a: t.line_to(_add(t.s.p, _point(a)), True) if a else None,
    "Pinpoint": lambda t, a: t.pinpoint(_add(_point(a), t.s.p, -1.0)) if a else None,
    "PinpointRel": lambda t, a: t.pinpoint(_point(a)) if a else None,
    "@R": _set_head,
    "EulerAngles": lambda t, a: t.euler(*[_real(x) for x in a[:3]]),
    "@v": lambda t, a: t.roll_to_vert(_real(a[0], 1.0) if a else 1.0),
    "@h": lambda t, a: t.roll_to_horizontal(_real(a[0], 1.0) if a else 1.0),
    "@D": lambda t, a: _scale_by(t, a, "set"),
    "@Di": lambda t, a: _scale_by(t, a, "mult"),
    "@Dd": lambda t, a: _scale_by(t, a, "div"),
    "@Tp": _tropism, "@Ts": _elasticity,
    "LeftReflection": _reflect(1), "UpReflection": _reflect(2), "HeadingReflection": _reflect(0),
}


# ----- L-Py's query pass (Lsystem::__turtle_interpretation with the environment turtle) -----
def has_query(rt) -> bool:
    """Whether the active production rules hold a query module (L-Py's `hasQuery`)."""
    from .lpy_derive import rule_table

    key = ("query", rt.group)
    got = rt._tables.get(key)
    if got is None:
        names = predefined_names()
        rules = {id(r): r for rs in rule_table(rt, "production").values() for r in rs}.values()
        got = any(names.get(p.name, p.name) in QUERIES
                  for r in rules for pats in (r.pred, r.left, r.right, r.new_left, r.new_right) for p in pats)
        rt._tables[key] = got
    return got


def fill_queries(rt, s: list) -> list:
    """`s` with its query modules holding the turtle's values where the turtle reads them."""
    turtle = LpyTurtle(rt.context.turtle.settings, rt.note)
    from .lpy_derive import max_depth

    out = list(s)
    skips, last = _quiet_branches(out, turtle.names)
    if last < 0:
        return out
    saved = rt.forward_dir
    rt.forward_dir = True
    try:
        _interpret(rt, out, turtle, max_depth(rt, "interpretation"), True, skips, last)
    finally:
        rt.forward_dir = saved
    return out


def _quiet_branches(s: list, names) -> tuple[dict, int]:
    """`[` index → its `]` for the branches that hold no query, and the last query's index.
    What the turtle does there cannot change a query's value: `]` restores the whole state, and
    nothing after the last query is read (this keeps a large string's guides from being walked
    again at every step; interpretation rules are not run there, which only a rule body with
    side effects on the model's globals could tell)."""
    skips: dict[int, int] = {}
    open_: list[list] = []  # [index, holds a query]
    last = -1
    for i, m in enumerate(s):
        name = m.name
        if name == "[":
            open_.append([i, False])
        elif name == "]" and open_:
            start, holds = open_.pop()
            if holds:
                if open_:
                    open_[-1][1] = True
            else:
                skips[start] = i
        elif names.get(name, name) in QUERIES:
            last = i
            if open_:
                open_[-1][1] = True
    return skips, last


def _interpret(rt, s: list, turtle: LpyTurtle, depth: int, top: bool, skips=None, last=None) -> None:
    """L-Py's `__gRecursiveInterpretation`: rules rewrite a module (their production is
    interpreted, again through the rules while depth remains); other modules are interpreted
    where they stand, and a query among them (in `s`, when `top`) is replaced by its answer."""
    from .lpy_derive import rule_table, try_rule
    from .lpy_match import end_of_branch

    table = rule_table(rt, "interpretation")
    stars = table["*"]
    names = turtle.names
    i, n = 0, len(s)
    if top:
        n = last + 1
        if "[" in table or stars:
            skips = {}
    while i < n:
        m = s[i]
        if top and i in skips:
            i = skips[i] + 1
            continue
        if m.name == "%":
            i = end_of_branch(s, i + 1)
            continue
        for rule in table.get(m.name, stars):
            got = try_rule(rt, rule, s, i, [], True)
            if got is None:
                continue
            produced, length = got
            if depth > 1:
                _interpret(rt, list(produced), turtle, depth - 1, False)
            else:
                for p in produced:
                    _one(turtle, p, names)
            i += length
            break
        else:
            answered = _one(turtle, m, names)
            if answered is not None and top:
                s[i] = answered
            i += 1


def _one(turtle: LpyTurtle, m, names):
    name = names.get(m.name, m.name)
    if name in QUERIES:
        return turtle.query(m)
    turtle.command(m)
    return None

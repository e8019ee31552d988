"""The turtle lpfg runs between steps to answer queries: `GetPos(x, y, z)`, `GetHead`,
`GetLeft`, `GetUp` receive the turtle's position or orientation where they stand, the string
being read through the interpretation rules as lpfg draws it. Only what moves or turns the
turtle counts (F, f, the turns and rolls, TurnAround, MoveTo, SB/EB); angles in degrees.
"""

import math

QUERIES = {"GetPos": "p", "GetHead": "h", "GetLeft": "l", "GetUp": "u"}
MOVES = {"F", "f", "Left", "Right", "Up", "Down", "RollL", "RollR", "Roll", "TurnAround", "SB",
         "EB", "MoveTo", "MoveTo3f", "MoveTo3d"}


def _rotate(a, b, degrees):
    """(a, b) turned by `degrees` in their plane: a towards b."""
    r = math.radians(degrees)
    c, s = math.cos(r), math.sin(r)
    return ([a[k] * c + b[k] * s for k in range(3)], [b[k] * c - a[k] * s for k in range(3)])


class Turtle:
    def __init__(self):
        self.p = [0.0, 0.0, 0.0]
        self.h = [0.0, 1.0, 0.0]
        self.l = [-1.0, 0.0, 0.0]
        self.u = [0.0, 0.0, 1.0]
        self.stack = []

    def command(self, name, args):
        a = float(args[0]) if args and isinstance(args[0], (int, float)) else None
        if name in ("F", "f") and a is not None:
            self.p = [self.p[k] + self.h[k] * a for k in range(3)]
        elif name in ("Left", "Right") and a is not None:
            self.h, self.l = _rotate(self.h, self.l, a if name == "Left" else -a)
        elif name in ("Up", "Down") and a is not None:
            self.h, self.u = _rotate(self.h, self.u, a if name == "Up" else -a)
        elif name in ("RollL", "RollR", "Roll") and a is not None:
            self.l, self.u = _rotate(self.l, self.u, -a if name == "RollL" else a)
        elif name == "TurnAround":
            self.h = [-v for v in self.h]
            self.l = [-v for v in self.l]
        elif name == "SB":
            self.stack.append((self.p, self.h, self.l, self.u))
        elif name == "EB" and self.stack:
            self.p, self.h, self.l, self.u = self.stack.pop()
        elif name in ("MoveTo", "MoveTo3f", "MoveTo3d") and len(args) >= 3:
            self.p = [float(v) for v in args[:3]]

    def answer(self, name, args):
        """The query module with the turtle's values in place of its parameters."""
        value = getattr(self, QUERIES[name])
        return (name, tuple(value[: len(args)]) + tuple(args[3:]))


ENVIRONMENT_QUERIES = {"E1": 1, "E2": 2, "EA20": 20}


def answer_queries(engine, s, environment):
    """`s` with its query modules answered (the turtle's, and the environment's when the
    object has one); unchanged when it has none."""
    asks = QUERIES if environment is None else {**QUERIES, **ENVIRONMENT_QUERIES}
    if not any(m[0] in asks for m in s):
        return s
    turtle = Turtle()
    interpreted = {name for _, name in engine.rules["interpretation"]}
    out = []
    pending = []  # (index in out, kind, vigor, position)
    for m in s:
        if m[0] in QUERIES:
            out.append(turtle.answer(m[0], m[1]))
            continue
        if environment is not None and m[0] in ENVIRONMENT_QUERIES and m[1]:
            first = m[1][0]
            if isinstance(first, list):  # EA20's 20 values: the first is the vigor and the reply
                first = first[0] if first else 0.0
            vigor = first if isinstance(first, (int, float)) else 0.0
            pending.append((len(out), ENVIRONMENT_QUERIES[m[0]], vigor, list(turtle.p)))
            out.append(m)
            continue
        out.append(m)
        if m[0] in interpreted:
            for c in engine.rewrite([m], "interpretation"):
                turtle.command(c[0], c[1])
        elif m[0] in MOVES:
            turtle.command(m[0], m[1])
    if pending:
        replies = environment.answer([(kind, vigor, p) for _, kind, vigor, p in pending])
        for (k, _, _, _), reply in zip(pending, replies):
            name, args = out[k]
            if isinstance(args[0], list):
                out[k] = (name, ([reply] + list(args[0][1:]),) + tuple(args[1:]))
            else:
                out[k] = (name, (reply,) + tuple(args[1:]))
    return out

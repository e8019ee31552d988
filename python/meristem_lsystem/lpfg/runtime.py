"""The names a translated L+C model runs with: C arithmetic (`_div`, `_mod`, `_int`), structs
and lpfg's vectors, the maths library, random numbers, function files, and lpfg's calls
(`Stop`, `Forward`, `Backward`, `UseGroup`, `Printf` …). One `Runtime` per run: no global state.
"""

import math
import random
import re
import sys
import struct
import time

from .functions import FunctionSet
from .lexer import LpfgError


class StopDerivation(Exception):
    pass


class _Struct:
    _fields = ()
    _types = ()
    _defaults = ()

    def __init__(self, *args):
        for name, make in zip(self._fields, self._defaults):
            object.__setattr__(self, name, make())
        ctor = getattr(self, f"_ctor_{len(args)}", None)
        if ctor is not None:
            ctor(*args)
            return
        for name, type_, value in zip(self._fields, self._types, args):
            object.__setattr__(self, name, _coerce(value, type_))

    def _copy(self):
        other = object.__new__(type(self))
        copied = other.__dict__
        for name, v in self.__dict__.items():
            t = type(v)
            copied[name] = v if t is float or t is int else _val(v)
        return other

    def __repr__(self):
        return "{" + ",".join(f"{n}:{getattr(self, n)!r}" for n in self._fields) + "}"


class _Vector(_Struct):
    def __add__(self, o):
        return type(self)(*[a + b for a, b in zip(self._values(), o._values())])

    def __sub__(self, o):
        return type(self)(*[a - b for a, b in zip(self._values(), o._values())])

    def __neg__(self):
        return type(self)(*[-a for a in self._values()])

    def __mul__(self, o):
        if isinstance(o, _Vector):  # lpfg: V3f * V3f is the dot product
            return sum(a * b for a, b in zip(self._values(), o._values()))
        return type(self)(*[a * o for a in self._values()])

    __rmul__ = __mul__

    def __truediv__(self, o):
        return type(self)(*[a / o for a in self._values()])

    def __mod__(self, o):  # lpfg: V3f % V3f is the cross product
        a, b = self._values(), o._values()
        return V3f(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def __eq__(self, o):
        return isinstance(o, _Vector) and self._values() == o._values()

    def _values(self):
        return [getattr(self, n) for n in self._fields]

    def Length(self):
        return math.sqrt(sum(a * a for a in self._values()))

    def Normalize(self):
        n = self.Length()
        if n > 0:
            for name in self._fields:
                object.__setattr__(self, name, getattr(self, name) / n)
        return self

    def Normalized(self):
        return self._copy().Normalize()

    def Set(self, *values):
        for name, v in zip(self._fields, values):
            object.__setattr__(self, name, float(v))


class V3f(_Vector):
    _fields = ("x", "y", "z")
    _types = ("float", "float", "float")
    _defaults = (float, float, float)


class V2f(_Vector):
    _fields = ("x", "y")
    _types = ("float", "float")
    _defaults = (float, float)


class MouseStatus(_Struct):
    """lpfg's mouse state: no mouse here, so nothing is ever pushed."""

    _fields = ("viewX", "viewY", "atFront", "atRear", "atMiddle", "lbDown", "lbPushed",
               "lbReleased", "mbDown", "mbPushed", "mbReleased", "rbDown", "rbPushed", "rbReleased",
               "cursorActive", "selectedModuleId")
    _types = ("int", "int", "V3f", "V3f", "V3f") + ("int",) * 11
    _defaults = (int, int, V3f, V3f, V3f) + (int,) * 11


class CameraPosition(_Struct):
    _fields = ("position", "lookat", "up", "scale", "upVector", "headVector")
    _types = ("V3f", "V3f", "V3f", "float", "V3f", "V3f")
    _defaults = (V3f, V3f, V3f, lambda: 1.0, V3f, V3f)


# lpfg's types that are structs of its own, with their fields' types (for the translator).
PREDEFINED_STRUCTS = {"MouseStatus": MouseStatus, "CameraPosition": CameraPosition}


class _Init:
    """A brace initialiser `{a, b, …}` before it knows what it initialises."""

    def __init__(self, items):
        self.items = items


def _coerce(value, type_):
    if type_ == "int":
        return _int(value)
    if type_ == "float":
        return float(value)
    if type_ == "f32":
        return _f32(value)
    return _val(value)


_F32 = struct.Struct("f")
_LINE_MARK = re.compile(r"#@(\d+)$")


def _f32(v):
    """A value stored in a C `float`: rounded to single precision."""
    v = float(v)
    try:
        return _F32.unpack(_F32.pack(v))[0]
    except OverflowError:
        return math.copysign(math.inf, v)


def _val(v):
    if isinstance(v, _Struct):
        return v._copy()
    if isinstance(v, list):
        return [_val(x) for x in v]
    return v


def _int(v):
    try:
        return int(v)
    except (OverflowError, ValueError):
        if isinstance(v, float):  # undefined in C; a PC's lpfg gets the "integer indefinite"
            if ZeroDivisionNote.notify is not None:
                ZeroDivisionNote.notify("conversion of an infinite or NaN value", -2147483648)
            return -2147483648
        raise LpfgError(f"cannot convert {v!r} to an integer")


def _bool(v):
    return 1 if v else 0


class ZeroDivisionNote:
    """Where an integer division or remainder by zero is noted (C leaves it undefined; the
    result is 0 and the run goes on, as a researcher opening the model expects a plant)."""

    notify = None


def _zero_int(what):
    if ZeroDivisionNote.notify is not None:
        ZeroDivisionNote.notify(f"{what} by zero", 0)
    return 0


def _log(x, base=None):
    """C's log: log(0) is -inf, a negative number's log is NaN."""
    if x == 0:
        return -math.inf
    if x < 0 or x != x:
        return math.nan
    return math.log(x) if base is None else math.log(x) / math.log(base)


def _div(a, b):
    if isinstance(a, int) and isinstance(b, int):
        if b == 0:
            return _zero_int("division")
        q = abs(a) // abs(b)
        return q if (a >= 0) == (b >= 0) else -q
    try:
        return a / b
    except ZeroDivisionError:
        if a == 0 or a != a:
            return math.nan
        return math.copysign(math.inf, a) * math.copysign(1.0, b)


def _mod(a, b):
    if isinstance(a, int) and isinstance(b, int):
        if b == 0:
            return _zero_int("remainder")
        r = abs(a) % abs(b)
        return r if a >= 0 else -r
    if isinstance(a, _Vector):
        return a % b  # lpfg's cross product
    return math.fmod(a, b)


def _last(*values):
    return values[-1]


def _setattr(obj, name, value):
    setattr(obj, name, value)
    return value


def _setitem(obj, index, value):
    obj[index] = value
    return value


def _array(n, make):
    return [make() for _ in range(int(n))]


def _init_array(init, struct):
    out = []
    for item in init.items:
        if isinstance(item, _Init):
            out.append(_init_struct(struct, item) if struct else _init_array(item, None))
        else:
            out.append(item)
    return out


def _init_struct(cls, init):
    obj = cls()
    for name, type_, value in zip(cls._fields, cls._types, init.items):
        if isinstance(value, _Init):
            value = value.items
        object.__setattr__(obj, name, _coerce(value, type_))
    return obj


_FORMAT = re.compile(r"%([-+ #0]*\d*(?:\.\d+)?)(?:hh|h|ll|l|L|z|j|t)?([diouxXeEfFgGcs%])")


def _sprintf(fmt, *args):
    """C's printf formatting (length modifiers such as `%ld` dropped)."""
    fmt = _FORMAT.sub(lambda m: "%" + m.group(1) + ("d" if m.group(2) in "iu" else m.group(2)), str(fmt))
    try:
        return fmt % tuple(args)
    except (TypeError, ValueError, OverflowError):
        return fmt


def _pow(a, b):
    try:
        return math.pow(a, b)
    except (ValueError, OverflowError):
        return math.nan


def _safe(f):
    def wrapped(*a):
        try:
            return f(*a)
        except (ValueError, OverflowError):
            return math.nan
    return wrapped


MATHS = {
    "sin": math.sin, "cos": math.cos, "tan": math.tan, "asin": _safe(math.asin),
    "acos": _safe(math.acos), "atan": math.atan, "atan2": math.atan2, "sqrt": _safe(math.sqrt),
    "exp": _safe(math.exp), "log": _log, "log10": lambda x: _log(x, 10),
    "pow": _pow, "fabs": lambda x: abs(float(x)), "abs": abs, "floor": lambda x: float(math.floor(x)),
    "ceil": lambda x: float(math.ceil(x)), "fmod": math.fmod, "fmin": min, "fmax": max,
    "min": min, "max": max, "sinh": math.sinh, "cosh": math.cosh, "tanh": math.tanh,
    "round": lambda x: float(math.floor(x + 0.5)) if x >= 0 else -float(math.floor(-x + 0.5)),
    "M_PI": math.pi, "M_PI_2": math.pi / 2, "M_E": math.e, "RAND_MAX": 2147483647,
    "MAXFLOAT": 3.4028234663852886e38, "FLT_MAX": 3.4028234663852886e38, "HUGE_VAL": math.inf,
    "INT_MAX": 2147483647, "EOF": -1,
}


# lpfg's calls that read files this runtime does not read: an error naming the construct.
UNSUPPORTED_CALLS = {
    **{name: "lpfg's contour and curve files (.con, .crv) are not read here" for name in (
        "curveX", "curveY", "curveZ", "curveXY", "curveXYZ", "curveXYf", "curveXYd",
        "curveXYZf", "curveXYZd")},
    "Interpolate": "lpfg's B-spline surface objects are not reproduced",
    "GetSurface": "lpfg's B-spline surface objects are not reproduced",
}


class Runtime:
    """The per-run state that lpfg's calls change, and the namespace the model runs in."""

    def __init__(self, files, seed, time_limit, notes):
        self.rng = random.Random(seed)
        self.deadline = time.monotonic() + time_limit
        self.time_limit = time_limit
        self.notes = notes
        self.noted = set()
        self.functions = FunctionSet(files, notes)
        self.buffer = []
        self.direction = "forward"
        self.group = 0
        self.stop = False
        self.step = 0
        self.line = 0  # the line of the production running, for notes
        self.source_lines = []  # the translated source, for the lines of notes
        self.max_modules = 2_000_000
        self.environment_on = True
        self.propensity = 1.0  # the rate the last ggroup production gave
        ZeroDivisionNote.notify = self.zero_division

    def zero_division(self, what, value):
        line = self.model_line() or self.line
        key = ("undefined", what, line)
        if key not in self.noted:
            self.noted.add(key)
            self.notes.append({"line": line, "message": f"integer {what} (undefined in C) gave {value}"})

    def model_line(self):
        """The L+C line of the innermost translated code running (its `#@line` mark)."""
        frame = sys._getframe(1)
        while frame is not None:
            if frame.f_code.co_filename == "<lpfg>":
                k = frame.f_lineno - 1
                if 0 <= k < len(self.source_lines):
                    mark = _LINE_MARK.search(self.source_lines[k])
                    if mark:
                        return int(mark.group(1))
            frame = frame.f_back
        return 0

    def tick(self):
        if time.monotonic() > self.deadline:
            raise LpfgError(f"stopped after the time limit of {self.time_limit:g} s (a loop that does not end?)")

    def note_once(self, key, message):
        if key not in self.noted:
            self.noted.add(key)
            self.notes.append({"line": self.model_line(), "message": message})

    def namespace(self):
        ns = dict(MATHS)
        ns.update({
            "_Struct": _Struct, "V3f": V3f, "V2f": V2f, "V3d": V3f, "V2d": V2f, "_Init": _Init,
            "_val": _val, "_int": _int, "_f32": _f32, "_bool": _bool, "_div": _div, "_mod": _mod,
            "_last": _last, "_setattr": _setattr, "_setitem": _setitem, "_array": _array,
            "_init_array": _init_array, "_init_struct": _init_struct, "_sprintf": _sprintf,
            "_np": self.nproduce, "_PRODUCED": True, "_tick": self.tick,
            "ran": lambda x=1.0: self.rng.random() * x, "rand": lambda: self.rng.randrange(2147483648),
            "srand": lambda s=0: self.rng.seed(int(s)), "srand48": lambda s=0: self.rng.seed(int(s)),
            "drand48": self.rng.random, "random": lambda: self.rng.randrange(2147483648),
            "uniform": lambda a=0.0, b=1.0: a + (b - a) * self.rng.random(),
            "func": self.functions.value, "tfunc": self.functions.timeline, "val": self.functions.val,
            "_propensity": self.set_propensity, "SeedGillespie": lambda s=0: self.rng.seed(int(s)),
            "expf": _safe(math.exp), "sqrtf": _safe(math.sqrt), "powf": _pow, "fabsf": lambda x: abs(float(x)),
            "logf": _log, "sinf": math.sin, "cosf": math.cos, "floorf": lambda x: float(math.floor(x)),
            "IsForward": lambda: 1 if self.direction == "forward" else 0,
            "Environment": lambda: self.set_environment(True),
            "NoEnvironment": lambda: self.set_environment(False),
            "UserMenuItem": lambda *a: None, "UserMenuChoice": self.menu_choice,
            "Stop": self.do_stop, "Forward": lambda: self.set_direction("forward"),
            "Backward": lambda: self.set_direction("backward"), "UseGroup": self.use_group,
            "CurrentGroup": lambda: self.group, "getDerivationStep": lambda: self.step,
            "CurrentDerivationStep": lambda: self.step,
            "Printf": self.printf, "printf": self.printf,
            "fprintf": lambda stream, *a: self.printf(*a) if stream is None else 0,
            "fflush": lambda *a: 0, "puts": lambda text: self.printf(str(text) + "\n"),
            "UseView": self.ignored("UseView", "lpfg opens a window per view; here only the first view is drawn"),
            "CloseView": lambda *a: 0,
            "DisplayFrame": self.ignored("DisplayFrame", "animation frames are not written"),
            "fopen": self.no_file, "fclose": lambda *a: 0,
            "stdout": None, "stderr": None, "exit": self.do_exit, "assert": lambda c: None,
            "MouseStatus": MouseStatus, "CameraPosition": CameraPosition,
            "GetMouseStatus": self.mouse, "GetCameraPosition": lambda *a: CameraPosition(),
            "RunSimulation": lambda: None, "PauseSimulation": lambda: None,
            "StopSimulation": lambda: None, "terrainVisibilityAll": lambda *a: None,
            "Shaded": 0, "Wireframe": 1, "Hidden": 2,
        })
        for name in UNSUPPORTED_CALLS:
            ns[name] = self.unsupported(name)
        return ns

    def unsupported(self, name):
        def call(*args):
            raise LpfgError(f"{name}: {UNSUPPORTED_CALLS[name]}")
        return call

    def mouse(self):
        self.note_once("mouse", "GetMouseStatus: an interactive model; here the mouse never moves "
                       "or clicks, so what it would add by hand is not drawn")
        return MouseStatus()

    def printf(self, fmt="", *args):
        """What the model prints (`Printf`, `printf`, `fprintf(stdout …)`) goes to standard
        output, which `run` keeps as the result's `output`."""
        text = _sprintf(fmt, *args)
        sys.stdout.write(text)
        return len(text)

    def nproduce(self, *modules):
        self.buffer.extend(modules)
        if len(self.buffer) > self.max_modules:
            raise LpfgError(f"one successor grew beyond {self.max_modules} modules")

    def set_environment(self, on):
        """lpfg's Environment()/NoEnvironment(): whether the step before each derivation runs
        (the turtle's queries and the environmental program)."""
        self.environment_on = on

    def menu_choice(self):
        self.note_once("menu", "UserMenuChoice: the model's own menu is not shown; no item is ever chosen (-1)")
        return -1

    def set_propensity(self, rate):
        self.propensity = float(rate)

    def do_stop(self):
        self.stop = True

    def do_exit(self, code=0):
        raise StopDerivation()

    def set_direction(self, d):
        self.direction = d

    def use_group(self, g):
        self.group = int(g)

    def ignored(self, name, why):
        def call(*args):
            self.note_once(name, f"{name}: {why}")
            return 0
        return call

    def no_file(self, name="", mode="r", *rest):
        if "r" in str(mode):
            raise LpfgError(f"fopen({name!r}): reading files from a model is not available")
        self.note_once("fopen", f"fopen({name!r}): files the model writes are not written")
        return None

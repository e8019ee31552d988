"""Modules and strings of modules (`Lstring`), as L-Py's Python API shows them.

A `Module` is a name and a list of parameters; `Lstring` is a list of modules with the few
`AxialTree` methods models call. `format_lstring` writes a string back in L-Py's module syntax,
the form the result's `lstring` carries (see python/README.md)."""

from __future__ import annotations

import math

# Predefined L-Py modules: primary name first, then its aliases (src/cpp/predefinedmodules.cpp).
PREDEFINED = [
    ("[", "SB"), ("]", "EB"), ("F",), ("f",), ("nF",), ("X", "MouseIns"), ("%", "Cut"),
    ("*", "any"), ("?P", "GetPos"), ("?H", "GetHead"), ("?U", "GetUp"), ("?L", "GetLeft"),
    ("?R", "GetRight"), ("?F", "GetFrame"), ("@Gc", "StartGC"), ("@Ge", "EndGC"),
    ("{", "BP"), ("}", "EP"), (".", "PP"), ("@M", "MoveTo"), ("MoveRel",), ("LineTo",),
    ("OLineTo",), ("Pinpoint",), ("LineRel",), ("OLineRel",), ("PinpointRel",),
    ("@R", "SetHead"), ("EulerAngles",), ("+", "Left"), ("-", "Right"), ("^", "Up"),
    ("&", "Down"), ("/", "RollL"), ("\\", "RollR"), ("iRollL",), ("iRollR",),
    ("|", "TurnAround"), ("@v", "RollToVert"), ("@h", "RollToHorizontal"), ("@O", "Sphere"),
    ("@B", "Box"), ("@b", "Quad"), ("@o", "Circle"), ("@L", "Label"), ("_", "IncWidth"),
    ("!", "DecWidth"), ("SetWidth",), (";", "IncColor"), (",", "DecColor"), ("SetColor",),
    ("InterpolateColors",), ("TextureBaseColor",), ("InterpolateTextureBaseColors",),
    ("@Dd", "DivScale"), ("@Di", "MultScale"), ("@D", "SetScale"), ("surface",), ("~",),
    ("@g", "PglShape"), ("Frame",), ("Arrow",), ("@Ts", "Elasticity"), ("@Tp", "Tropism"),
    ("SetContour",), ("SectionResolution",), ("SetGuide",), ("EndGuide",), ("Sweep",),
    ("PositionOnGuide",), ("TextureScale",), ("TextureUScale",),
    ("TextureVScale", "TextureVCoeff"), ("TextureTranslation",), ("TextureRotation",),
    ("TextureTransformation",), ("LeftReflection",), ("UpReflection",),
    ("HeadingReflection",), ("@2D", "StartScreenProjection"), ("@3D", "EndScreenProjection"),
    ("?I", "GetIterator"), ("$", "GetModule"), ("new", "newmodule"), ("=]",), ("x", "repexp", "all"),
    ("or", "||"),
]

# Names that are only meaningful in patterns or string manipulation, never declared by default
# as drawable modules of a user string (`x`, `or`, `new` are reserved in patterns only).
PATTERN_ONLY = {"x", "or", "=]", "?I", "$"}


def predefined_names() -> dict[str, str]:
    """Every predefined name and alias → the module's primary name."""
    table: dict[str, str] = {}
    for names in PREDEFINED:
        if names[0] in PATTERN_ONLY:
            continue
        for name in names:
            table[name] = names[0]
    return table


class Module:
    """One module: `name` and `args` (a list), plus named parameters from `module A(x, y)`."""

    __slots__ = ("name", "args")
    named: dict[str, dict[str, int]] = {}

    def __init__(self, name, args=None, *more):
        if isinstance(name, Module):
            self.name, self.args = name.name, list(name.args)
            return
        self.name = name
        if more:
            self.args = [args, *more]
        elif args is None:
            self.args = []
        elif isinstance(args, list):
            self.args = args
        elif isinstance(args, tuple):
            self.args = list(args)
        else:
            self.args = [args]

    def __len__(self):
        return len(self.args)

    def __getitem__(self, i):
        return self.args[i]

    def __setitem__(self, i, v):
        self.args[i] = v

    def __getattr__(self, attr):
        try:
            index = Module.named[object.__getattribute__(self, "name")][attr]
        except KeyError:
            raise AttributeError(attr) from None
        return self.args[index]

    def __setattr__(self, attr, value):
        if attr in ("name", "args"):
            object.__setattr__(self, attr, value)
            return
        index = Module.named.get(self.name, {}).get(attr)
        if index is None:
            raise AttributeError(attr)
        self.args[index] = value

    def __eq__(self, other):
        if isinstance(other, str):
            return self.name == other
        return isinstance(other, Module) and self.name == other.name and self.args == other.args

    def __hash__(self):
        return hash(self.name)

    def __repr__(self):
        return format_module(self)

    __str__ = __repr__

    def argSize(self):
        return len(self.args)

    def hasParameter(self, name):
        return name in Module.named.get(self.name, {})

    def getParameter(self, name):
        return getattr(self, name)

    def setParameter(self, name, value):
        setattr(self, name, value)

    def append(self, value):
        self.args.append(value)

    def copy(self):
        return Module(self.name, list(self.args))

    def __copy__(self):
        return self.copy()

    def __deepcopy__(self, memo):
        import copy

        return Module(self.name, copy.deepcopy(self.args, memo))


_new_module = object.__new__
_set_name = Module.name.__set__
_set_args = Module.args.__set__


def make_module(name: str, args: list) -> Module:
    """The fast constructor the translated rules call (`__M`)."""
    m = _new_module(Module)
    _set_name(m, name)
    _set_args(m, args)
    return m


class Lstring(list):
    """A string of modules, with the `AxialTree` navigation models use."""

    def __init__(self, value=()):
        if isinstance(value, (str, Module)) or (type(value) is not list and not isinstance(value, Lstring)):
            value = to_modules(value)
        list.__init__(self, value)

    def __getitem__(self, i):
        got = list.__getitem__(self, i)
        return Lstring(got) if isinstance(i, slice) else got

    def __add__(self, other):
        return Lstring(list.__add__(self, to_modules(other)))

    def __iadd__(self, other):
        self.extend(to_modules(other))
        return self

    def __str__(self):
        return format_lstring(self)

    __repr__ = __str__

    def append(self, m):
        if isinstance(m, (list, tuple)) and not isinstance(m, Module):
            self.extend(to_modules(m))
        else:
            list.append(self, m if isinstance(m, Module) else Module(str(m)))

    def count(self, name):
        return sum(1 for m in self if m.name == name)

    def parent(self, i):
        depth = 0
        j = i - 1
        while j >= 0:
            n = self[j].name
            if n == "]":
                depth += 1
            elif n == "[":
                if depth:
                    depth -= 1
            elif depth == 0:
                return j
            j -= 1
        return None

    def endBracket(self, i):
        depth = 0
        for j in range(i, len(self)):
            n = list.__getitem__(self, j).name
            if n == "[":
                depth += 1
            elif n == "]":
                if depth == 0:
                    return j
                depth -= 1
        return len(self)

    def successor(self, i):
        j = i + 1
        while j < len(self) and list.__getitem__(self, j).name == "[":
            j = self.endBracket(j + 1) + 1
        if j < len(self) and list.__getitem__(self, j).name != "]":
            return j
        return None

    def children(self, i):
        out = []
        j = i + 1
        while j < len(self):
            n = list.__getitem__(self, j).name
            if n == "[":
                if j + 1 < len(self) and list.__getitem__(self, j + 1).name not in "[]":
                    out.append(j + 1)
                j = self.endBracket(j + 1) + 1
            elif n == "]":
                break
            else:
                out.append(j)
                break
        return out


AxialTree = Lstring


class StringReader:
    """Reads module strings given as text at run time (`Lstring("F(1)A")`): set by the run."""

    current = None


def to_modules(value) -> list:
    """A production's value (Lstring, list of modules/names/tuples, a string) as modules."""
    if isinstance(value, Module):
        return [value]
    if isinstance(value, str):
        if StringReader.current is None:
            raise TypeError("a string of modules outside a model run")
        return StringReader.current(value)
    out = []
    for item in value:
        if isinstance(item, Module):
            out.append(item)
        elif isinstance(item, str):
            out.extend(to_modules(item))
        elif isinstance(item, (tuple, list)) and item and isinstance(item[0], str):
            out.append(Module(item[0], list(item[1:])))
        elif isinstance(item, (tuple, list)):
            out.extend(to_modules(item))
        else:
            raise TypeError(f"cannot make a module of {item!r}")
    return out


def format_number(v) -> str:
    if isinstance(v, bool):
        return "1" if v else "0"
    if isinstance(v, int):
        return repr(v)
    if isinstance(v, float):
        if math.isfinite(v):
            return repr(v)
        return "0"
    return repr(float(v))


class ObjectTable:
    """Non-numeric parameters (curves, patches …) met while formatting: `@obj<k>` → description."""

    current: "ObjectTable | None" = None

    def __init__(self):
        self.objects: list[dict] = []
        self.ids: dict[int, int] = {}

    def ref(self, value) -> str:
        k = self.ids.get(id(value))
        if k is None:
            k = len(self.objects)
            self.ids[id(value)] = k
            describe = getattr(value, "describe", None)
            self.objects.append(describe() if describe else {"type": type(value).__name__})
        return f"@obj{k}"


def format_arg(v) -> str:
    t = type(v)
    if t is float:
        return repr(v) if v - v == 0 else "0"
    if t is int:
        return repr(v)
    if isinstance(v, (bool, int, float)):
        return format_number(v)
    if isinstance(v, str):
        return repr(v)
    if v is None:
        return "None"
    items = getattr(v, "__meristem_numbers__", None)
    if items is not None:
        return ",".join(format_number(x) for x in items())
    if isinstance(v, (tuple, list)) and all(isinstance(x, (int, float)) for x in v):
        return ",".join(format_number(x) for x in v)
    try:
        return format_number(float(v))
    except (TypeError, ValueError):
        pass
    table = ObjectTable.current
    return table.ref(v) if table else repr(v)


def format_module(m: Module) -> str:
    if not m.args:
        return m.name
    args = m.args
    if m.name == "~" and isinstance(args[0], str):
        rest = args[1:]
        return "~" + args[0] + (f"({','.join(format_arg(a) for a in rest)})" if rest else "")
    return f"{m.name}({','.join(format_arg(a) for a in args)})"


def _is_word_char(c: str) -> bool:
    return c.isalnum() or c == "_"


def format_lstring(modules) -> str:
    """Modules in L-Py's syntax; a blank separates two names that would otherwise fuse."""
    out = []
    prev_word = 0  # length of the previous name when it could fuse with the next one
    for m in modules:
        name, args = m.name, m.args
        if args:
            text = format_module(m)
        else:
            text = name
        if prev_word and _is_word_char(text[0]) and (len(name) > 1 or prev_word > 1):
            out.append(" ")
        out.append(text)
        prev_word = len(name) if not args and _is_word_char(name[-1]) else 0
    return "".join(out)

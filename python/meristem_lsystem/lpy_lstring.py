"""Reading L-Py module strings: `F(x*2)[+(30)A(x-1)]` → modules with Python argument text.

Follows L-Py's parser (src/cpp/lpy_parser.cpp, `parselstring`/`parseAModule`): blanks separate
modules, `#` starts a comment, a name is the longest declared or predefined name at that place
(else one character), `~l` is the surface `l`, and parameters are the text between balanced
parentheses (Python expressions, left to Python)."""

from __future__ import annotations

from dataclasses import dataclass


class LpySyntaxError(Exception):
    def __init__(self, message: str, line: int, column: int = 1):
        super().__init__(message)
        self.message, self.line, self.column = message, line, column


@dataclass
class ModuleText:
    name: str  # the primary name
    args: str | None  # the text between the parentheses, None when there are none
    surface: str | None = None  # `~l`: the surface's name
    offset: int = 0


class NameTable:
    """Module names usable in strings: predefined ones, aliases, and the model's declarations."""

    def __init__(self, predefined: dict[str, str]):
        self.names = dict(predefined)
        self.lengths: dict[str, list[int]] = {}  # first character → name lengths, longest first
        for name in self.names:
            self._index(name)

    def _index(self, name: str):
        lengths = self.lengths.setdefault(name[0], [])
        if len(name) not in lengths:
            lengths.append(len(name))
            lengths.sort(reverse=True)

    def declare(self, name: str, alias_of: str | None = None):
        self.names[name] = self.names.get(alias_of, alias_of) if alias_of else name
        self._index(name)

    def match(self, text: str, i: int) -> tuple[str, int]:
        for w in self.lengths.get(text[i], ()):
            primary = self.names.get(text[i : i + w])
            if primary is not None:
                return primary, w
        return text[i], 1


def skip_string(text: str, i: int) -> int:
    """`i` at a quote: the index after the matching quote (triple quotes included)."""
    q = text[i]
    if text.startswith(q * 3, i):
        end = text.find(q * 3, i + 3)
        return len(text) if end < 0 else end + 3
    j = i + 1
    while j < len(text) and text[j] != q:
        if text[j] == "\\":
            j += 1
        j += 1
    return j + 1


def closing_paren(text: str, i: int, line: int) -> int:
    """`i` just after an opening parenthesis: the index of its closing one."""
    depth = 0
    j = i
    while j < len(text):
        c = text[j]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                return j
            depth -= 1
        elif c in "'\"":
            j = skip_string(text, j)
            continue
        elif c == "#":
            nl = text.find("\n", j)
            j = len(text) if nl < 0 else nl
            continue
        j += 1
    raise LpySyntaxError("unclosed '(' in module parameters", line)


PATTERN_WORDS = (("all", "x"), ("x", "x"), ("or", "or"), ("?I", "?I"))


def pattern_word(text: str, i: int) -> tuple[str, int] | None:
    """`x(`/`all(` (repetition), `or(` and `?I` read as pattern constructs at `i`."""
    for word, name in PATTERN_WORDS:
        if text.startswith(word, i):
            j = i + len(word)
            while j < len(text) and text[j] in " \t":
                j += 1
            if name == "?I" or (j < len(text) and text[j] == "("):
                return name, len(word)
    return None


def parse_modules(text: str, names: NameTable, line: int = 0, pattern: bool = False) -> list[ModuleText]:
    out: list[ModuleText] = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c in " \t\r\n":
            i += 1
            continue
        if c == "#":
            nl = text.find("\n", i)
            i = n if nl < 0 else nl
            continue
        if c in "()":
            raise LpySyntaxError(f"found a module named '{c}'", line + text.count("\n", 0, i))
        start = i
        special = pattern_word(text, i) if pattern else None
        name, width = special or names.match(text, i)
        i += width
        surface = None
        if name == "~" and i < n and text[i] not in "( \t\n":
            surface = text[i]
            i += 1
        elif name == "$":
            # `$Name(var)` in a pattern binds the whole module; `$var` in a successor emits it
            j = i
            while j < n and (text[j].isalnum() or text[j] == "_"):
                j += 1
            if j == i:
                raise LpySyntaxError("'$' must be followed by a name", line + text.count("\n", 0, i))
            surface, i = text[i:j], j
        j = i
        while j < n and text[j] in " \t":
            j += 1
        args = None
        if j < n and text[j] == "(":
            end = closing_paren(text, j + 1, line + text.count("\n", 0, j))
            args = text[j + 1 : end]
            i = end + 1
        out.append(ModuleText(name, args, surface, start))
    return out


def split_args(text: str) -> list[str]:
    """Top-level comma-separated pieces of a parameter text."""
    parts, depth, start, j = [], 0, 0, 0
    while j < len(text):
        c = text[j]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c in "'\"":
            j = skip_string(text, j)
            continue
        elif c == "," and depth == 0:
            parts.append(text[start:j])
            start = j + 1
        j += 1
    if text[start:].strip() or parts:
        parts.append(text[start:])
    return [p.strip() for p in parts]


def to_python(text: str, names: NameTable, line: int = 0) -> str:
    """A successor string as a Python list expression of modules (`__M(name, [args])`)."""
    items = []
    for m in parse_modules(text, names, line):
        if m.name == "$":
            items.append(f"__Mcopy({m.surface})")
            continue
        args = m.args or ""
        if m.name in ("*", "new"):
            # `*(name, args…)` / `new(name, args…)`: a module whose name is computed;
            # a bare `*` produces nothing (L-Py: `produce *` erases the module)
            if args.strip():
                items.append(f"__Mstar({args})")
            continue
        if m.surface is not None:
            args = repr(m.surface) + ("," + args if args.strip() else "")
        items.append(f"__M({m.name!r},[{args}])")
    return "[" + ",".join(items) + "]"

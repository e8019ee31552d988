"""Matching rules against a string: predecessor, contexts with brackets and ignored modules.

As in L-Py (src/cpp/lsysrule.cpp, matching.cpp): a pattern module matches a module of the same
name and the same number of parameters (a `*args` takes the rest); a left context walks back
over ignored modules and closed branches and up to the parent across `[`; a right context walks
forward over ignored modules and skips branches, and `[`/`]` in the pattern enter and leave
them. Parameters are bound in the header's order."""

from __future__ import annotations

BRACKETS = ("[", "]")


class Pattern:
    """A compiled pattern module: name and per-parameter tests."""

    __slots__ = ("name", "specs", "nfixed", "star")

    def __init__(self, name, specs):
        self.name = name
        self.specs = specs  # list of (kind, value): "var" | "const" (a value) | "star"
        self.star = bool(specs) and specs[-1][0] == "star"
        self.nfixed = len(specs) - (1 if self.star else 0)

    def bind(self, m, out: list) -> bool:
        """Appends the bound values to `out`; False (out untouched) when `m` does not match."""
        args = m.args
        specs = self.specs
        if specs and specs[0][0] == "module":
            # `$Name(m)`: the whole module, whatever its parameters
            if self.name != m.name:
                return False
            out.append(m)
            return True
        if self.name == "*":
            # `*(name, args…)`: the first spec takes the name
            if not specs:
                return True
            args = [m.name, *args]
        elif self.name != m.name:
            return False
        n = len(args)
        if self.star:
            if n < self.nfixed:
                return False
        elif n != self.nfixed:
            return False
        mark = len(out)
        for k in range(self.nfixed):
            kind, value = specs[k]
            if kind == "var":
                out.append(args[k])
            elif kind == "cond":
                if not value(args[k]):
                    del out[mark:]
                    return False
                out.append(args[k])
            elif args[k] != value:
                del out[mark:]
                return False
        if self.star:
            out.append(list(args[self.nfixed :]))
        return True


class ContextFilter:
    """Which modules contexts see: all but `ignore`, or only `consider` (brackets always)."""

    def __init__(self, ignore: set, consider: set):
        self.ignore = set(ignore) - set(BRACKETS)
        self.consider = set(consider) | set(BRACKETS) if consider else None

    def skipped(self, name: str) -> bool:
        if self.consider is not None:
            return name not in self.consider
        return name in self.ignore


def match_pred(pred: list, s: list, i: int, out: list) -> int:
    """Matches the predecessor at `i`; its length, or 0."""
    if i + len(pred) > len(s):
        return 0
    mark = len(out)
    for k, p in enumerate(pred):
        if not p.bind(s[i + k], out):
            del out[mark:]
            return 0
    return len(pred)


def match_left(pats: list, s: list, i: int, out: list, filt: ContextFilter) -> bool:
    """Matches a left context ending just before `i` (bound in left-to-right order)."""
    got = []
    j = i - 1
    for p in reversed(pats):
        while True:
            if j < 0:
                return False
            name = s[j].name
            if name == "]":
                depth = 1
                j -= 1
                while j >= 0 and depth:
                    n = s[j].name
                    if n == "]":
                        depth += 1
                    elif n == "[":
                        depth -= 1
                    j -= 1
                continue
            if name == "[" or filt.skipped(name):
                j -= 1
                continue
            break
        part = []
        if not p.bind(s[j], part):
            return False
        got.append(part)
        j -= 1
    for part in reversed(got):
        out.extend(part)
    return True


def end_of_branch(s: list, j: int) -> int:
    """Index of the `]` closing the branch that holds `j`, or len(s)."""
    depth = 0
    while j < len(s):
        n = s[j].name
        if n == "[":
            depth += 1
        elif n == "]":
            if depth == 0:
                return j
            depth -= 1
        j += 1
    return len(s)


def match_right(pats: list, pi: int, s, j: int, out: list, filt: ContextFilter) -> bool:
    """Matches `pats[pi:]` from `j` onwards."""
    return right_end(pats, pi, s, j, out, filt) >= 0


def skip_ignored(s, j: int, n: int, filt: ContextFilter) -> int:
    while j < n and s[j].name not in BRACKETS and filt.skipped(s[j].name):
        j += 1
    return j


def right_end(pats: list, pi: int, s, j: int, out: list, filt: ContextFilter) -> int:
    """Matches `pats[pi:]` from `j`; the index after the match, or -1.

    Long because: one walk handles the bracket cases and the repetition `x(...)` together."""
    n = len(s)
    while pi < len(pats):
        p = pats[pi]
        j = skip_ignored(s, j, n, filt)
        if p.name == "]":
            j = end_of_branch(s, j)
            if j >= n:
                return -1
            j += 1
            pi += 1
            continue
        if p.name == "x" and p.specs and p.specs[0][0] == "repeat":
            j = repeat(p.specs[0][1], s, j, out, filt)
            pi += 1
            continue
        if j >= n:
            return -1
        name = s[j].name
        if p.name == "[":
            while j < n and s[j].name == "[":
                mark = len(out)
                end = right_end(pats, pi + 1, s, j + 1, out, filt)
                if end >= 0:
                    return end
                del out[mark:]
                j = skip_ignored(s, end_of_branch(s, j + 1) + 1, n, filt)
            return -1
        if name == "[":
            j = end_of_branch(s, j + 1) + 1
            continue
        if name == "]":
            return -1
        if not p.bind(s[j], out):
            return -1
        j += 1
        pi += 1
    return j


def repeat(inner: list, s, j: int, out: list, filt: ContextFilter) -> int:
    """`x(pattern)`: the pattern as many times as it matches; each variable gets the list of
    its values (L-Py's repetition in contexts, e.g. `>> x([I(w)])` for every child branch)."""
    columns: list | None = None
    while True:
        trial: list = []
        end = right_end(inner, 0, s, j, trial, filt)
        if end < 0 or end <= j:
            break
        if columns is None:
            columns = [[] for _ in trial]
        for column, value in zip(columns, trial):
            column.append(value)
        j = end
    out.extend(columns if columns is not None else [[] for _ in range(count_vars(inner))])
    return j


def count_vars(pats: list) -> int:
    total = 0
    for p in pats:
        for kind, value in p.specs:
            if kind == "repeat":
                total += count_vars(value)
            elif kind != "const":
                total += 1
    return total


class Reversed:
    """A backwards-built string seen from left to right (for `>>` when deriving backwards)."""

    __slots__ = ("items",)

    def __init__(self, items: list):
        self.items = items

    def __len__(self):
        return len(self.items)

    def __getitem__(self, j):
        return self.items[len(self.items) - 1 - j]

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


def match_right(pats: list, pi: int, s: list, j: int, out: list, filt: ContextFilter) -> bool:
    """Matches `pats[pi:]` from `j` onwards."""
    n = len(s)
    while pi < len(pats):
        p = pats[pi]
        while j < n and s[j].name not in BRACKETS and filt.skipped(s[j].name):
            j += 1
        if p.name == "]":
            j = end_of_branch(s, j)
            if j >= n:
                return False
            j += 1
            pi += 1
            continue
        if j >= n:
            return False
        name = s[j].name
        if p.name == "[":
            while j < n and s[j].name == "[":
                mark = len(out)
                if match_right(pats, pi + 1, s, j + 1, out, filt):
                    return True
                del out[mark:]
                j = end_of_branch(s, j + 1) + 1
                while j < n and s[j].name not in BRACKETS and filt.skipped(s[j].name):
                    j += 1
            return False
        if name == "[":
            j = end_of_branch(s, j + 1) + 1
            continue
        if name == "]":
            return False
        if not p.bind(s[j], out):
            return False
        j += 1
        pi += 1
    return True

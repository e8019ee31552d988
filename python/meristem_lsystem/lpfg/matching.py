"""Context matching in a bracketed string of modules `(name, args)`, as lpfg does it: a left
context skips whole branches `SB … EB` and steps out of the branch it is in; a right context
skips branches that its pattern does not enter and fails at the end of its branch; a pattern's
`EB` skips to the end of the current branch; `ignore:`/`consider:` modules are passed over.
"""


class Skipper:
    def __init__(self, ignore, consider):
        self.ignore = frozenset(ignore)
        self.consider = frozenset(consider) if consider is not None else None

    def skips(self, name):
        if name in ("SB", "EB"):
            return False
        if self.consider is not None:
            return name not in self.consider
        return name in self.ignore


class Reversed:
    """`seq` read from its end: the new string to the right when deriving backward."""

    __slots__ = ("seq", "n")

    def __init__(self, seq):
        self.seq = seq
        self.n = len(seq)

    def __len__(self):
        return self.n

    def __getitem__(self, k):
        return self.seq[self.n - 1 - k]


def _after_branch(seq, j):
    """Index after the EB closing the SB at j."""
    depth = 0
    n = len(seq)
    while j < n:
        name = seq[j][0]
        if name == "SB":
            depth += 1
        elif name == "EB":
            depth -= 1
            if depth == 0:
                return j + 1
        j += 1
    return n


def _before_branch(seq, j):
    """Index before the SB opening the EB at j."""
    depth = 0
    while j >= 0:
        name = seq[j][0]
        if name == "EB":
            depth += 1
        elif name == "SB":
            depth -= 1
            if depth == 0:
                return j - 1
        j -= 1
    return -1


def match_right(seq, j, pattern, skipper):
    found = match_right_end(seq, j, pattern, skipper)
    return None if found is None else found[0]


def match_right_end(seq, j, pattern, skipper):
    """(parameters, index after the match) or None."""
    args = []
    n = len(seq)
    for name, arity in pattern:
        if name == "EB":
            depth = 0
            while j < n:
                m = seq[j][0]
                if m == "SB":
                    depth += 1
                elif m == "EB":
                    if depth == 0:
                        break
                    depth -= 1
                j += 1
            if j >= n:
                return None
            j += 1
            continue
        while j < n:
            m = seq[j][0]
            if m == "SB" and name != "SB":
                j = _after_branch(seq, j)
            elif m != name and skipper.skips(m):
                j += 1
            else:
                break
        if j >= n:
            return None
        module = seq[j]
        if module[0] != name or len(module[1]) != arity:
            return None
        args.extend(module[1])
        j += 1
    return args, j


def match_left(seq, i, pattern, skipper):
    args = []
    j = i - 1
    for name, arity in reversed(pattern):
        while j >= 0:
            m = seq[j][0]
            if m == "EB":
                j = _before_branch(seq, j)
            elif m == "SB" or (m != name and skipper.skips(m)):
                j -= 1
            else:
                break
        if j < 0:
            return None
        module = seq[j]
        if module[0] != name or len(module[1]) != arity:
            return None
        args[0:0] = module[1]
        j -= 1
    return args


def match_strict(seq, start, pattern):
    """The predecessor: modules side by side, same names and numbers of parameters."""
    if start < 0 or start + len(pattern) > len(seq):
        return None
    args = []
    for k, (name, arity) in enumerate(pattern):
        module = seq[start + k]
        if module[0] != name or len(module[1]) != arity:
            return None
        args.extend(module[1])
    return args

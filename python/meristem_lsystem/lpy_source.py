"""Translating an .lpy file into Python source plus a table of rules, line for line.

L-Py (src/cpp/lpy_parser.cpp) turns a model into Python code: the L-system sections become
assignments (`Axiom:` → `__axiom__ = …`), each rule becomes a function whose `produce X` is a
`return` of the successor's modules, and `nproduce X` appends modules. We do the same, keeping
every .lpy line on the same line of the generated code, so a Python error's line number IS the
model's line. The rules' predecessors and contexts are read into `RuleSpec`s for the engine."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from .lpy_lstring import LpySyntaxError, NameTable, parse_modules, skip_string, split_args, to_python

INIT_TAG = "###### INITIALISATION ######"
RULE_KINDS = {"production": "production", "decomposition": "decomposition",
              "interpretation": "interpretation", "homomorphism": "interpretation"}
CODE_STARTS = ("def ", "class ", "import ", "from ", "@", "global ", "if ", "for ", "while ",
               "try:", "with ", "print(", "print ")
PRINT2 = re.compile(r"(\s*)print\s+([^(\s=].*?)\s*$")
COND = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\s*(==|!=|<=|>=|<|>|\bin\b|\bnot\s+in\b|\bis\b)")
IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


class Unsupported(Exception):
    """A pattern construct this runtime does not match: its rule is left out, with a note."""


@dataclass
class PatternModule:
    name: str
    specs: list  # ("var", name) | ("star", name) | ("const", python text)


@dataclass
class RuleSpec:
    kind: str
    group: int
    line: int
    function: str
    pred: list[PatternModule]
    left: list[PatternModule] = field(default_factory=list)
    right: list[PatternModule] = field(default_factory=list)
    new_left: list[PatternModule] = field(default_factory=list)
    new_right: list[PatternModule] = field(default_factory=list)
    static: bool = False


@dataclass
class LpySource:
    code: str  # the model's Python, line for line
    init_code: str | None  # the INITIALISATION section, padded to its lines, or None
    rules: list[RuleSpec]
    names: NameTable
    declared: dict[str, list[str]]  # module name → named parameters
    ignore: set[str] = field(default_factory=set)
    consider: set[str] = field(default_factory=set)
    notes: list[dict] = field(default_factory=list)


def find_top(text: str, token: str, start: int = 0, opening: str = "([{", closing: str = ")]}") -> int:
    """Index of `token` outside strings, comments and brackets, or -1."""
    depth, j = 0, start
    while j < len(text):
        c = text[j]
        if c in "'\"":
            j = skip_string(text, j)
            continue
        if c == "#":
            return -1
        if c in opening:
            depth += 1
        elif c in closing:
            depth -= 1
        elif depth == 0 and text.startswith(token, j):
            return j
        j += 1
    return -1


def declare_modules(text: str, names: NameTable, declared: dict, line: int):
    """`module A(x, y), B = A, C : scale = 1`: names, named parameters and aliases."""
    comment = find_top(text, "#")
    text = text if comment < 0 else text[:comment]
    if "#" in text:
        text = text.split("#", 1)[0]
    body = text.split(":", 1)[0] if find_top(text, ":") >= 0 else text
    for piece in split_args(body):
        if not piece:
            continue
        if "=" in piece and "(" not in piece.split("=", 1)[0]:
            name, target = (p.strip() for p in piece.split("=", 1))
            names.declare(name, target)
            continue
        name, _, params = piece.partition("(")
        name = name.strip()
        if not name:
            raise LpySyntaxError("empty module name in declaration", line)
        names.declare(name)
        params = params.rstrip().rstrip(")")
        declared[name] = [p.strip() for p in params.split(",") if p.strip()]


def pattern(text: str, names: NameTable, line: int) -> list[PatternModule]:
    out = []
    for m in parse_modules(text, names, line, pattern=True):
        if m.name in ("?I", "or"):
            raise Unsupported(f"'{m.name}' patterns are not available")
        if m.name == "x" and m.args and m.args.strip():
            out.append(PatternModule("x", [("repeat", pattern(m.args, names, line))]))
            continue
        if m.name == "$":
            target = names.names.get(m.surface, m.surface)
            out.append(PatternModule(target, [("module", (m.args or "").strip() or "_")]))
            continue
        specs = []
        if m.surface is not None:
            specs.append(("const", repr(m.surface)))
        for arg in split_args(m.args or ""):
            if IDENT.match(arg):
                specs.append(("var", arg))
            elif arg.startswith("*") and IDENT.match(arg.lstrip("*")):
                specs.append(("star", arg.lstrip("*")))
            elif COND.match(arg):
                name, test = COND.match(arg).groups()
                specs.append(("cond", (name, arg)))
            else:
                specs.append(("const", arg))
        out.append(PatternModule(m.name, specs))
    return out


def split_header(header: str) -> dict[str, str]:
    """`cg < ncg << pred >> ncd > cd` → its five parts (empty when absent)."""
    segs, seps, depth, start, j = [], [], 0, 0, 0
    while j < len(header):
        c = header[j]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c in "'\"":
            j = skip_string(header, j)
            continue
        elif depth == 0 and c in "<>":
            sep = header[j : j + 2] if header[j : j + 2] in ("<<", ">>") else c
            segs.append(header[start:j])
            seps.append(sep)
            j += len(sep)
            start = j
            continue
        j += 1
    segs.append(header[start:])
    parts = {"left": "", "new_left": "", "pred": "", "new_right": "", "right": ""}
    nleft = sum(1 for s in seps if s in ("<", "<<"))
    for k, sep in enumerate(seps):
        if sep == "<":
            parts["left"] = segs[k]
        elif sep == "<<":
            parts["new_left"] = segs[k]
        elif sep == ">>":
            parts["new_right"] = segs[k + 1]
        else:
            parts["right"] = segs[k + 1]
    parts["pred"] = segs[nleft]
    return parts


def pattern_params(part: list) -> list[str]:
    params = []
    for pm in part:
        for kind, value in pm.specs:
            if kind == "repeat":
                params.extend(pattern_params(value))
            elif kind == "cond":
                params.append(value[0])
            elif kind != "const":
                params.append(value)
    return params


def rule_params(spec: RuleSpec) -> list[str]:
    """The rule function's parameters, in the header's order; `*args` arrive as one list."""
    params = []
    for part in (spec.left, spec.new_left, spec.pred, spec.new_right, spec.right):
        params.extend(pattern_params(part))
    # named modules the header binds twice would be a Python error: L-Py refuses them too
    return params


def transform_code(line: str, names: NameTable, lineno: int, produce: bool) -> str:
    """`produce X` → `return __produce([...])`, `nproduce X` → `__nproduce([...])`."""
    out, j, last = [], 0, 0
    while j < len(line):
        c = line[j]
        if c in "'\"":
            j = skip_string(line, j)
            continue
        if c == "#":
            break
        word = None
        for kw in ("nproduce", "produce", "makestring"):
            if line.startswith(kw, j) and (j == 0 or not (line[j - 1].isalnum() or line[j - 1] in "_."))\
                    and not (line[j + len(kw) : j + len(kw) + 1].isalnum() or line[j + len(kw) : j + len(kw) + 1] == "_"):
                word = kw
                break
        if word is None or (word == "produce" and not produce):
            j += 1
            continue
        k = j + len(word)
        while k < len(line) and line[k] in " \t":
            k += 1
        if k < len(line) and line[k] == "(":
            from .lpy_lstring import closing_paren

            end = closing_paren(line, k + 1, lineno)
            text, after = line[k + 1 : end], end + 1
        else:
            text, after = line[k:], len(line)
        expr = to_python(text, names, lineno)
        out.append(line[last:j])
        if word == "produce":
            out.append(f"return __produce({expr})")
        elif word == "nproduce":
            out.append(f"__nproduce({expr})")
        else:
            out.append(f"Lstring({expr})")
        last = j = after
    out.append(line[last:])
    return "".join(out)


SUCCESSOR_LINE = re.compile(r"-->|-static->|\bn?produce\b")


def balance(line: str) -> int:
    """Open parentheses left at the line's end (strings and comments skipped)."""
    depth, j = 0, 0
    while j < len(line):
        c = line[j]
        if c in "'\"":
            j = skip_string(line, j)
            continue
        if c == "#":
            break
        depth += (c == "(") - (c == ")")
        j += 1
    return depth


def join_continued_successors(lines: list[str]) -> list[str]:
    """A successor whose parentheses close on later lines is joined into its first line; the
    lines it took stay, blank, so every other line keeps its number."""
    lines = list(lines)
    for i, line in enumerate(lines):
        if not SUCCESSOR_LINE.search(line) or balance(line) <= 0:
            continue
        joined, k = line, i + 1
        while balance(joined) > 0 and k < len(lines) and k - i <= 30:
            joined += " " + lines[k].strip()
            lines[k] = ""
            k += 1
        lines[i] = joined
    return lines


def keyword(line: str, *words: str) -> str | None:
    """The text after `word:` when the line starts with one of `words` followed by ':'."""
    for w in words:
        if line.startswith(w):
            rest = line[len(w) :].lstrip()
            if rest.startswith(":"):
                return rest[1:]
    return None


def collect_declarations(lines: list[str], names: NameTable, declared: dict):
    for no, line in enumerate(lines, 1):
        if re.match(r"modules?\s", line) and not re.match(r"modules?\s*=", line):
            declare_modules(re.sub(r"^modules?\s", "", line), names, declared, no)


def translate(text: str, predefined: dict[str, str]) -> LpySource:
    """Long because: one pass over the lines with the section state, as L-Py's parser does."""
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    init_code = None
    cut = text.find(INIT_TAG)
    if cut >= 0:
        init_code = "\n" * text.count("\n", 0, cut) + text[cut:]
        text = text[:cut]
    lines = join_continued_successors(text.split("\n"))
    names = NameTable(predefined)
    declared: dict[str, list[str]] = {}
    collect_declarations(lines, names, declared)
    src = LpySource("", init_code, [], names, declared)
    out: list[str] = []
    mode, kind, group, body = "code", "production", 0, None
    in_triple = None
    for no, line in enumerate(lines, 1):
        if "print" in line:
            line = python2_print(line)
        stripped = line.strip()
        if in_triple:
            out.append(line)
            if line.count(in_triple) % 2 == 1:
                in_triple = None
            continue
        at_col0 = bool(line) and line[0] not in " \t"
        if not at_col0 or stripped.startswith("#") or not stripped:
            if body in ("rule", "code", "axiom") and stripped and not stripped.startswith("#"):
                out.append(transform_code(line, names, no, body != "code"))
            else:
                out.append(transform_code(line, names, no, False) if stripped else line)
            for q in ('"""', "'''"):
                if line.count(q) % 2 == 1:
                    in_triple = q
            continue
        body = None
        depth = keyword(line, "maximum depth", "maximum_depth")
        if depth is not None:
            out.append(f"__maximum_depth_{kind}__ = {depth.strip()}")
            continue
        following = next((l for l in lines[no:] if l.strip() and not l.strip().startswith("#")), "")
        handled = section_line(line, no, src, out, names, following[:1] in (" ", "\t"))
        if handled is not None:
            new_mode, kind_or_none, group_or_none, body = handled
            mode = new_mode or mode
            kind = kind_or_none or kind
            group = group if group_or_none is None else group_or_none
            continue
        if mode == "rules" and is_rule_header(line) and not re.match(r"[A-Za-z_][\w.]*\s*(\[.*\])?\s*[-+*/]?=[^=]", line):
            out.append(rule_line(line, no, src, kind, group))
            body = "rule"
            continue
        out.append(transform_code(line, names, no, False))
        body = "code"
        for q in ('"""', "'''"):
            if line.count(q) % 2 == 1:
                in_triple = q
    src.code = "\n".join(out)
    return src


def is_rule_header(line: str) -> bool:
    """In a rules section, a line at column 0 is a rule unless it is plain Python."""
    if find_top(line, "-->", 0, "(", ")") >= 0 or find_top(line, "-static->", 0, "(", ")") >= 0:
        return True
    if line.startswith("@"):
        return line.rstrip().endswith(":") or find_top(line, ":", 0, "(", ")") >= 0
    if line.startswith(CODE_STARTS):
        return False
    return not re.match(r"[A-Za-z_][\w.]*\s*(\[.*\])?\s*[-+*/]?=[^=]", line)


def python2_print(line: str) -> str:
    """`print x, y` (Python 2, in older models) → `print(x, y)`."""
    m = PRINT2.match(line)
    return f"{m.group(1)}print({m.group(2)})" if m else line


def section_line(line, no, src: LpySource, out, names, indented_next: bool = False):
    """A section keyword at column 0: its Python line, and (mode, kind, group, body) or None."""
    rest = keyword(line, "Axiom", "axiom")
    if rest is not None:
        if rest.strip() and not rest.strip().startswith("#"):
            out.append(f"__axiom__ = {to_python(rest, names, no)}")
            return None, None, None, None
        if not indented_next:
            out.append("__axiom__ = []")
            return None, None, None, None
        out.append("def __axiom__():")
        return None, None, None, "axiom"
    if re.match(r"modules?\s", line) and not re.match(r"modules?\s*=", line):
        out.append("")
        return None, None, None, None
    for words, var in ((("derivation length", "derivation_length"), "__derivation_length__"),):
        rest = keyword(line, *words)
        if rest is not None:
            out.append(f"{var} = {rest.strip() or 'None'}")
            return None, None, None, None
    for word, kind in RULE_KINDS.items():
        rest = keyword(line, word)
        if rest is not None:
            out.append("")
            return "rules", kind, None, None
    for word, target in (("ignore", src.ignore), ("consider", src.consider)):
        rest = keyword(line, word)
        if rest is not None:
            target.update(m.name for m in parse_modules(rest, names, no))
            out.append("")
            return None, None, None, None
    m = re.match(r"group\s+(\d+)\s*:", line)
    if m:
        out.append("")
        return None, None, int(m.group(1)), None
    if re.match(r"endgroup\b", line):
        out.append("")
        return None, None, 0, None
    if re.match(r"endlsystem\b", line):
        out.append("")
        return "code", None, 0, None
    return None


def rule_line(line: str, no: int, src: LpySource, kind: str, group: int) -> str:
    arrow, width, static = find_top(line, "-->", 0, "(", ")"), 3, False
    if arrow < 0:
        arrow = find_top(line, "-static->", 0, "(", ")")
        width, static = 9, arrow >= 0
    colon = find_top(line, ":", 0, "(", ")")
    if arrow < 0 and colon < 0:
        raise LpySyntaxError("a rule needs '-->' or ':' after its predecessor", no, 1)
    cut = arrow if arrow >= 0 and (colon < 0 or arrow < colon) else colon
    header = split_header(line[:cut])
    try:
        spec = RuleSpec(kind, group, no, f"__rule_{len(src.rules)}__",
                        pattern(header["pred"], src.names, no), pattern(header["left"], src.names, no),
                        pattern(header["right"], src.names, no), pattern(header["new_left"], src.names, no),
                        pattern(header["new_right"], src.names, no), static)
    except Unsupported as e:
        src.notes.append({"line": no, "message": f"rule left out: {e}"})
        name = f"__unused_rule_{no}__"
        if cut == arrow:
            return f"def {name}(*args): pass"
        rest = line[colon + 1 :]
        return f"def {name}(*args):" + (" " + transform_code(rest, src.names, no, True) if rest.strip() else "")
    if not spec.pred:
        raise LpySyntaxError("a rule without a predecessor", no, 1)
    src.rules.append(spec)
    head = f"def {spec.function}({', '.join(rule_params(spec))}):"
    if cut == arrow:
        succ = line[arrow + width :]
        return f"{head} return __produce({to_python(succ, src.names, no)})"
    rest = line[colon + 1 :]
    if rest.strip().startswith("@static"):
        rest = rest.replace("@static", "", 1)
        spec.static = True
    if rest.strip() and not rest.strip().startswith("#"):
        return head + " " + transform_code(rest, src.names, no, True)
    return head

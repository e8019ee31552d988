"""The C preprocessor of L+C: `#include`, `#define` (object- and function-like), `#undef`,
`#if`/`#ifdef`/`#ifndef`/`#elif`/`#else`/`#endif`.

`#include` of the object's own files inlines them (files arrive as a dict); lpfg's and the
C library's headers (`lpfg.h`, `lpfgall.h`, `math.h`, `stdio.h` …) are known and skipped.
The result is one flat list of tokens, each keeping the line and column it came from.
"""

from .lexer import LpfgError, tokenize_lines

# Headers that lpfg or the C/C++ library provide: their names are built in.
SYSTEM_HEADERS = {
    "lpfg.h", "lpfgall.h", "lintrfc.h", "lsys.h", "math.h", "cmath", "stdio.h", "cstdio",
    "stdlib.h", "cstdlib", "string.h", "cstring", "memory.h", "assert.h", "time.h",
    "iostream", "fstream", "vector", "algorithm", "float.h", "limits.h", "stdarg.h",
    "utility", "string", "cassert", "ctime", "climits", "cfloat", "stddef.h",
}


class Preprocessor:
    def __init__(self, files, notes):
        self.files = files
        self.notes = notes
        self.macros = {}  # name -> (params or None, body tokens)

    def run(self, name, depth=0):
        if depth > 20:
            raise LpfgError(f"#include nested too deeply at {name}")
        out = []
        stack = []  # (active, taken) per open #if
        pending = []  # text lines since the last directive, expanded together
        for line in tokenize_lines(self.files[name]):
            if not line:
                continue
            active = all(entry[0] for entry in stack)
            if line[0][1] == "#" and line[0][0] == "op":
                out.extend(self.expand(pending, set()))
                pending = []
                self._directive(line, stack, active, out, depth)
            elif active:
                pending.extend(line)
        out.extend(self.expand(pending, set()))
        if stack:
            raise LpfgError("#if without #endif", *stack[-1][2])
        return out

    def _directive(self, line, stack, active, out, depth):
        if len(line) < 2:
            return
        word, rest = line[1][1], line[2:]
        here = (line[0][2], line[0][3])
        if word in ("ifdef", "ifndef"):
            if not rest:
                raise LpfgError(f"#{word} needs a name", *here)
            defined = rest[0][1] in self.macros
            cond = defined if word == "ifdef" else not defined
            stack.append((cond, cond, here))
        elif word == "if":
            cond = bool(self._condition(rest, here)) if active else False
            stack.append((cond, cond, here))
        elif word in ("elif", "else", "endif"):
            if not stack:
                raise LpfgError(f"#{word} without #if", *here)
            if word == "endif":
                stack.pop()
                return
            _, taken, opened = stack.pop()
            outer = all(entry[0] for entry in stack)
            if word == "else":
                cond = not taken
            else:
                cond = (not taken) and outer and bool(self._condition(rest, here))
            stack.append((cond, taken or cond, opened))
        elif not active:
            return
        elif word == "define":
            self._define(rest, here)
        elif word == "undef":
            if rest:
                self.macros.pop(rest[0][1], None)
        elif word == "include":
            self._include(rest, out, depth, here)
        elif word in ("pragma", "line", "warning"):
            return
        elif word == "error":
            raise LpfgError("#error " + " ".join(t[1] for t in rest), *here)
        else:
            raise LpfgError(f"unknown directive #{word}", *here)

    def _define(self, rest, here):
        if not rest or rest[0][0] != "id":
            raise LpfgError("#define needs a name", *here)
        name = rest[0]
        params = None
        body = rest[1:]
        # A function-like macro has '(' right after its name, with no space.
        if body and body[0][1] == "(" and body[0][3] == name[3] + len(name[1]):
            params = []
            i = 1
            while i < len(body) and body[i][1] != ")":
                if body[i][1] != ",":
                    params.append(body[i][1])
                i += 1
            body = body[i + 1 :]
        self.macros[name[1]] = (params, body)

    def _include(self, rest, out, depth, here):
        if not rest:
            raise LpfgError("#include needs a file", *here)
        if rest[0][0] == "str":
            target = rest[0][1][1:-1]
        else:
            target = "".join(t[1] for t in rest).strip("<>")
        base = target.split("/")[-1]
        if base in self.files:
            out.extend(self.run(base, depth + 1))
        elif base in SYSTEM_HEADERS:
            return
        else:
            self.notes.append({"line": here[0], "message": f"#include {target}: not among the object's files, skipped"})

    def _condition(self, tokens, here):
        resolved = []
        i = 0
        while i < len(tokens):
            t = tokens[i]
            if t[1] == "defined":
                j = i + 1
                paren = j < len(tokens) and tokens[j][1] == "("
                if paren:
                    j += 1
                name = tokens[j][1] if j < len(tokens) else ""
                resolved.append(("num", "1" if name in self.macros else "0", t[2], t[3]))
                i = j + (2 if paren else 1)
                continue
            resolved.append(t)
            i += 1
        words = []
        for t in self.expand(resolved, set()):
            v = t[1]
            if t[0] == "id":
                v = {"true": "1", "false": "0"}.get(v, "0")
            elif t[0] == "num":
                v = v.rstrip("uUlLfF") or "0"
            else:
                v = {"&&": " and ", "||": " or ", "!": " not ", "/": "//"}.get(v, v)
            words.append(v)
        try:
            return eval("".join(words), {"__builtins__": {}}, {})  # the model's own #if
        except Exception:
            raise LpfgError("cannot evaluate #if condition", *here)

    def expand(self, tokens, hidden):
        """Macro expansion of a token list (rescanning, a macro never expands inside itself)."""
        out = []
        i = 0
        while i < len(tokens):
            t = tokens[i]
            macro = self.macros.get(t[1]) if t[0] == "id" and t[1] not in hidden else None
            if macro is None:
                out.append(t)
                i += 1
                continue
            params, body = macro
            if params is None:
                out.extend(self.expand(_relocate(body, t), hidden | {t[1]}))
                i += 1
                continue
            if i + 1 >= len(tokens) or tokens[i + 1][1] != "(":
                out.append(t)
                i += 1
                continue
            args, i = _collect_args(tokens, i + 2, t)
            args = [self.expand(a, hidden) for a in args]
            substituted = []
            for b in body:
                if b[0] == "id" and b[1] in params:
                    k = params.index(b[1])
                    substituted.extend(args[k] if k < len(args) else [])
                else:
                    substituted.append(b)
            out.extend(self.expand(_relocate(substituted, t), hidden | {t[1]}))
        return out


def _relocate(body, at):
    return [(b[0], b[1], at[2], at[3]) for b in body]


def _collect_args(tokens, i, at):
    args, current, depth = [], [], 0
    while i < len(tokens):
        v = tokens[i][1]
        if v in "([{" and tokens[i][0] == "op":
            depth += 1
        elif v in ")]}" and tokens[i][0] == "op":
            if depth == 0:
                args.append(current)
                return [a for a in args if a or len(args) > 1], i + 1
            depth -= 1
        if v == "," and depth == 0:
            args.append(current)
            current = []
        else:
            current.append(tokens[i])
        i += 1
    raise LpfgError(f"macro {at[1]}: missing ')'", at[2], at[3])


def preprocess(files, main, notes):
    """Token list of `main` after preprocessing."""
    return Preprocessor(files, notes).run(main)

"""Tokens of L+C source: C++ tokens with their line and column, grouped by line.

Comments go (a `/* */` comment that spans lines keeps the line count), a backslash at
the end of a line joins it to the next (for `#define`). Tokens are tuples
`(kind, value, line, column)` with kind one of `id`, `num`, `str`, `chr`, `op`.
"""

import re


class LpfgError(Exception):
    """An error in the model, at its line and column (1-based)."""

    def __init__(self, message, line=0, column=0):
        super().__init__(message)
        self.message = message
        self.line = line
        self.column = column


_TOKEN = re.compile(
    r"""
    (?P<ws>[ \t\r\f\v]+)
  | (?P<num>(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[fFlLuU]*|0[xX][0-9a-fA-F]+[uUlL]*)
  | (?P<id>[A-Za-z_][A-Za-z_0-9]*)
  | (?P<str>"(?:[^"\\\n]|\\.)*")
  | (?P<chr>'(?:[^'\\\n]|\\.)+')
  | (?P<op><<=|>>=|\.\.\.|::|->|\+\+|--|<<|>>|<=|>=|==|!=|&&|\|\||\+=|-=|\*=|/=|%=|&=|\|=|\^=|\#\#|[-+*/%<>=!&|^~?:;,.()\[\]{}\#])
    """,
    re.VERBOSE,
)


def strip_comments(text):
    """Replaces comments by spaces, keeping every newline (so lines keep their numbers)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == '"' or c == "'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(text[i : j + 1])
            i = j + 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join("\n" if ch == "\n" else " " for ch in text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def tokenize_lines(text):
    """The source as a list of logical lines, each a list of tokens."""
    text = strip_comments(text.replace("\r\n", "\n"))
    lines = []
    pending = []
    for number, raw in enumerate(text.split("\n"), start=1):
        joined = raw.endswith("\\")
        body = raw[:-1] if joined else raw
        pending.extend(_tokens_of(body, number))
        if not joined:
            lines.append(pending)
            pending = []
    if pending:
        lines.append(pending)
    return lines


def _tokens_of(line_text, number):
    tokens = []
    pos = 0
    while pos < len(line_text):
        m = _TOKEN.match(line_text, pos)
        if not m:
            raise LpfgError(f"unexpected character {line_text[pos]!r}", number, pos + 1)
        kind = m.lastgroup
        if kind != "ws":
            tokens.append((kind, m.group(), number, pos + 1))
        pos = m.end()
    return tokens

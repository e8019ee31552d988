"""A cursor over preprocessed tokens, and the names C++ types are spelled with."""

from .lexer import LpfgError

SCALAR_TYPES = {
    "int": "int", "float": "f32", "double": "float", "bool": "bool", "char": "int",
    "long": "int", "short": "int", "unsigned": "int", "signed": "int", "size_t": "int",
    "void": "void", "FILE": "handle", "VisibilityMode": "int",
}
QUALIFIERS = {"const", "static", "inline", "extern", "volatile", "register", "struct", "mutable"}
VECTOR_TYPES = {"V3f": "V3f", "V3d": "V3f", "V2f": "V2f", "V2d": "V2f", "V3i": "V3f", "V2i": "V2f"}


class Cursor:
    def __init__(self, tokens):
        self.tokens = tokens
        self.pos = 0

    def peek(self, k=0):
        i = self.pos + k
        return self.tokens[i] if i < len(self.tokens) else ("eof", "", self._last_line(), 0)

    def _last_line(self):
        return self.tokens[-1][2] if self.tokens else 1

    def at(self, value, k=0):
        t = self.peek(k)
        return t[1] == value and t[0] in ("op", "id")

    def next(self):
        t = self.peek()
        if t[0] == "eof":
            raise LpfgError("unexpected end of file", t[2], t[3])
        self.pos += 1
        return t

    def accept(self, value):
        if self.at(value):
            self.pos += 1
            return True
        return False

    def expect(self, value):
        t = self.peek()
        if not self.at(value):
            shown = t[1] or "end of file"
            raise LpfgError(f"expected '{value}', found '{shown}'", t[2], t[3])
        self.pos += 1
        return t

    def ident(self):
        t = self.peek()
        if t[0] != "id":
            raise LpfgError(f"expected a name, found '{t[1] or 'end of file'}'", t[2], t[3])
        self.pos += 1
        return t[1]

    def error(self, message, token=None):
        t = token or self.peek()
        return LpfgError(message, t[2], t[3])

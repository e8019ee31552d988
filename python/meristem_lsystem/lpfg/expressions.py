"""C++ expressions of L+C translated to Python expressions.

C's meaning is kept where Python's differs: `/` and `%` go through `_div`/`_mod` (truncating
integer division when both sides are integers, C's remainder), comparisons and logic give
numbers usable in arithmetic, assignments and `++`/`--` inside expressions become `:=` or a
helper that returns the value, casts truncate towards zero. Every binary operation is
parenthesised, so Python's chained comparisons never apply.
"""

from .cursor import SCALAR_TYPES, VECTOR_TYPES, Cursor

PY_RESERVED = {
    "and", "as", "assert", "async", "await", "class", "def", "del", "elif", "except", "finally",
    "from", "global", "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise",
    "try", "with", "yield", "None", "True", "False", "print", "len", "int", "float", "list",
    "type", "object", "str", "id", "range", "self", "round", "sum", "map", "dict", "set", "iter",
    "next", "input", "open", "exec", "eval", "vars", "format", "hash", "bool", "tuple", "super",
}

# name -> (precedence, python operator or helper); higher binds tighter.
BINARY = {
    "||": (1, "or"), "&&": (2, "and"), "|": (3, "|"), "^": (4, "^"), "&": (5, "&"),
    "==": (6, "=="), "!=": (6, "!="), "<": (7, "<"), ">": (7, ">"), "<=": (7, "<="), ">=": (7, ">="),
    "<<": (8, "<<"), ">>": (8, ">>"), "+": (9, "+"), "-": (9, "-"),
    "*": (10, "*"), "/": (10, "_div"), "%": (10, "_mod"),
}
# C's arithmetic types: `float` is single precision (f32), `double` a Python float.
SCALARS = ("int", "float", "f32", "bool")
ASSIGN_OPS = {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="}
CONSTANTS = {"true": "True", "false": "False", "NULL": "None", "nullptr": "None"}


def py_name(name):
    return name + "_" if name in PY_RESERVED or name.startswith("_") else name


class Expr:
    """A translated expression: its Python code, what it assigns to when it is an lvalue
    (`('name', code)`, `('attr', object code, field)`, `('index', array code, index code)`),
    and its C type when known."""

    __slots__ = ("code", "lv", "type")

    def __init__(self, code, lv=None, type_=None):
        self.code = code
        self.lv = lv
        self.type = type_


def coerce(code, type_):
    if type_ == "int":
        return f"_int({code})"
    if type_ == "float":
        return f"float({code})"
    if type_ == "f32":
        return f"_f32({code})"
    if type_ == "bool":
        return f"_bool({code})"
    return f"_val({code})"


def binary_code(op, left, right):
    if op in ("_div", "_mod"):
        return f"{op}({left}, {right})"
    if op in ("or", "and"):
        return f"_bool({left} {op} {right})"
    return f"({left} {op} {right})"


CONTEXT_CALLS = {
    "InLeftContext": ("left", False), "InRightContext": ("right", False),
    "InNewLeftContext": ("left", True), "InNewRightContext": ("right", True),
}


class ContextCalls:
    """`InRightContext(SB() X(a) EB())` and its kin: true when the pattern is found next to the
    predecessor, binding its parameters to the (declared) variables named in it. Called again
    at the same place (a `while`), a pattern that starts with a branch finds the next branch."""

    def context_call(self, name):
        side, new = CONTEXT_CALLS[name]
        self.expect("(")
        pattern, names = [], []
        while not self.accept(")"):
            module = self.ident()
            arity = 0
            if self.accept("("):
                while not self.accept(")"):
                    names.append(self.ident())
                    arity += 1
                    self.accept(",")
            pattern.append((module, arity))
        self.counter += 1
        holder = f"_cv{self.counter}"
        binds = []
        for k, var in enumerate(names):
            found = self.lookup(var)
            target = found.code if found is not None and found.lv[0] == "name" else py_name(var)
            binds.append(f"({target} := _val({holder}[{k}]))")
        bound = f"_last({', '.join(binds)}, 1)" if binds else "1"
        call = f"_in_context({side!r}, {new}, {self.counter}, {tuple(pattern)!r})"
        return Expr(f"_bool((({holder} := {call}) is not None) and {bound})", None, "int")


class ExpressionParser(Cursor, ContextCalls):
    """Needs from its subclass: `lookup(name) -> Expr | None`, `is_type_name(name)`,
    `field_type(struct type, field)`, `struct_names`."""

    def expression(self):
        e = self.assignment()
        while self.at(","):
            self.next()
            right = self.assignment()
            e = Expr(f"_last({e.code}, {right.code})", None, right.type)
        return e

    def assignment(self):
        start = self.pos
        left = self.ternary()
        t = self.peek()
        if t[0] == "op" and t[1] in ASSIGN_OPS:
            if left.lv is None:
                raise self.error(f"cannot assign to this expression", self.tokens[start])
            self.next()
            right = self.assignment()
            return Expr(self.assign_code(left, t[1], right, as_value=True), None, left.type)
        return left

    def assign_value(self, left, op, right):
        """The value a C assignment stores, coerced to the target's type."""
        if op == "=":
            value = right.code
        else:
            _, py = BINARY[op[:-1]]
            value = binary_code(py, left.code, right.code)
        return coerce(value, left.type)

    def assign_code(self, left, op, right, as_value):
        value = self.assign_value(left, op, right)
        kind = left.lv[0]
        if not as_value:
            return f"{left.code} = {value}"
        if kind == "name":
            return f"({left.code} := {value})"
        if kind == "attr":
            return f"_setattr({left.lv[1]}, {left.lv[2]!r}, {value})"
        return f"_setitem({left.lv[1]}, {left.lv[2]}, {value})"

    def ternary(self):
        cond = self.binary(1)
        if self.accept("?"):
            yes = self.assignment()
            self.expect(":")
            no = self.assignment()
            return Expr(f"({yes.code} if {cond.code} else {no.code})", None, yes.type or no.type)
        return cond

    def binary(self, level):
        left = self.unary()
        while True:
            t = self.peek()
            entry = BINARY.get(t[1]) if t[0] == "op" else None
            if entry is None or entry[0] < level:
                return left
            self.next()
            right = self.binary(entry[0] + 1)
            type_ = _result_type(t[1], left.type, right.type)
            left = Expr(binary_code(entry[1], left.code, right.code), None, type_)

    def unary(self):
        t = self.peek()
        if t[0] == "op":
            if t[1] in ("-", "+", "~"):
                self.next()
                e = self.unary()
                return Expr(f"({t[1]}{e.code})", None, e.type)
            if t[1] == "!":
                self.next()
                return Expr(f"_bool(not {self.unary().code})", None, "bool")
            if t[1] in ("++", "--"):
                self.next()
                e = self.unary()
                return self.step(e, t, prefix=True)
            if t[1] in ("*", "&"):
                self.next()  # pointers are the objects themselves
                return self.unary()
            if t[1] == "(" and self._is_cast():
                self.next()
                type_ = self.type_name()
                self.expect(")")
                e = self.unary()
                return Expr(coerce(e.code, type_) if type_ in SCALARS else e.code, None, type_)
        if t[0] == "id" and t[1] == "sizeof":
            raise self.error("sizeof is not supported")
        return self.postfix()

    def _is_cast(self):
        t = self.peek(1)
        if t[0] != "id" or not self.is_type_name(t[1]):
            return False
        k = 2
        while self.peek(k)[1] in ("*", "&") or self.peek(k)[1] in SCALAR_TYPES:
            k += 1
        return self.at(")", k)

    def step(self, e, token, prefix):
        if e.lv is None:
            raise self.error(f"{token[1]} needs a variable", token)
        sign = "+" if token[1] == "++" else "-"
        new = Expr(f"({e.code} {sign} 1)")
        code = self.assign_code(e, "=", new, as_value=True)
        if prefix:
            return Expr(code, None, e.type)
        back = "-" if sign == "+" else "+"
        return Expr(f"({code} {back} 1)", None, e.type)

    def postfix(self):
        e = self.primary()
        while True:
            t = self.peek()
            if t[1] == "[" and t[0] == "op":
                self.next()
                index = self.expression()
                self.expect("]")
                e = Expr(f"{e.code}[{index.code}]", ("index", e.code, index.code), _element(e.type))
            elif t[1] in (".", "->") and t[0] == "op":
                self.next()
                field = self.ident()
                if self.at("("):
                    args = self.arguments()
                    e = Expr(f"{e.code}.{field}({', '.join(args)})", None, None)
                else:
                    ftype = self.field_type(e.type, field)
                    e = Expr(f"{e.code}.{field}", ("attr", e.code, field), ftype)
            elif t[1] in ("++", "--") and t[0] == "op":
                self.next()
                e = self.step(e, t, prefix=False)
            else:
                return e

    def arguments(self):
        self.expect("(")
        args = []
        if not self.accept(")"):
            while True:
                args.append(self.assignment().code)
                if self.accept(")"):
                    break
                self.expect(",")
        return args

    def primary(self):
        t = self.next()
        kind, value = t[0], t[1]
        if kind == "num":
            return Expr(_number(value), None, "float" if _is_float(value) else "int")
        if kind == "str":
            code = value
            while self.peek()[0] == "str":  # "a" "b" is one string
                code = code[:-1] + self.next()[1][1:]
            return Expr(code, None, "str")
        if kind == "chr":
            return Expr(f"ord({value})", None, "int")
        if value == "(" and kind == "op":
            e = self.expression()
            self.expect(")")
            return Expr(f"({e.code})", e.lv, e.type)
        if value == "{" and kind == "op":
            return self.initializer_list()
        if kind != "id":
            raise self.error(f"unexpected '{value}' in an expression", t)
        if self.accept("::"):  # std::sin, ShapeData::SD_Square: the names are global here
            return self.primary()
        if value in CONSTANTS:
            return Expr(CONSTANTS[value], None, "bool")
        return self.named(t)

    def initializer_list(self):
        items = []
        if not self.accept("}"):
            while True:
                items.append(self.assignment().code)
                self.accept(",")
                if self.accept("}"):
                    break
        return Expr(f"_Init([{', '.join(items)}])", None, "init")

    def named(self, t):
        value = t[1]
        if value in SCALAR_TYPES and self.at("("):
            args = self.arguments()
            return Expr(coerce(args[0] if args else "0", SCALAR_TYPES[value]), None, SCALAR_TYPES[value])
        if self.at("("):
            return self.call(t)
        found = self.lookup(value)
        if found is not None:
            return found
        return Expr(py_name(value), None, None)

    def call(self, t):
        name = t[1]
        if name in CONTEXT_CALLS:
            return self.context_call(name)
        args = self.arguments()
        if name in VECTOR_TYPES:
            return Expr(f"{VECTOR_TYPES[name]}({', '.join(args)})", None, VECTOR_TYPES[name])
        if name in self.struct_names:
            return Expr(f"{py_name(name)}({', '.join(args)})", None, name)
        found = self.lookup(name)
        callee = found.code if found is not None else py_name(name)
        return Expr(f"{callee}({', '.join(args)})", None, self.return_type(name))


def _number(text):
    text = text.lower()
    if text.startswith("0x"):
        return str(int(text.rstrip("ul"), 16))
    body = text.rstrip("ful")
    if _is_float(text):
        if body.endswith("."):
            body += "0"
        if body.startswith("."):
            body = "0" + body
        return body
    if len(body) > 1 and body.startswith("0"):
        return str(int(body, 8))
    return body


def _is_float(text):
    t = text.lower()
    if t.startswith("0x"):
        return False
    return "." in t or "e" in t or t.endswith("f")


def _element(type_):
    if type_ and type_.endswith("[]"):
        return type_[:-2]
    return None


def _result_type(op, a, b):
    if op in ("==", "!=", "<", ">", "<=", ">=", "&&", "||"):
        return "int"
    if a in ("float", "f32") or b in ("float", "f32"):
        return "float"
    if a in ("int", "bool") and b in ("int", "bool"):
        return "int"
    return a or b

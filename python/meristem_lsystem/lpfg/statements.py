"""C++ statements and declarations of L+C bodies translated to Python statements.

Scopes follow C: a name declared in a block is a new Python name when it would shadow another
(`x` becomes `x_2`), so Python's function-wide scope never mixes two C variables. Loops keep
C's `continue` (a `for` runs its increment before continuing), `switch` falls through until a
`break`, `produce`/`nproduce` append modules to the successor (`produce` also returns).
"""

from .cursor import QUALIFIERS, SCALAR_TYPES, VECTOR_TYPES
from .expressions import Expr, ExpressionParser, coerce, py_name


# lpfg's array types: EA20Array is the 20 values an environment answers EA20 with.
ARRAY_TYPES = {"EA20Array": 20}


class Struct:
    def __init__(self, name):
        self.name = name
        self.fields = []  # (name, type, dims)
        self.methods = []  # python source lines

    def field_type(self, field):
        for name, type_, dims in self.fields:
            if name == field:
                return type_ + "[]" * len(dims)
        return None


class StatementTranslator(ExpressionParser):
    def __init__(self, tokens):
        super().__init__(tokens)
        self.lines = []
        self.indent = 0
        self.scopes = []
        self.globals = {}  # C name -> (python name, type)
        self.structs = {}
        self.typedefs = {}
        self.function_types = {}
        self.loops = []  # per open loop: the code `continue` must run first, or None
        self.self_struct = None
        self.counter = 0

    # --- names -------------------------------------------------------------------------
    @property
    def struct_names(self):
        return self.structs

    def is_type_name(self, name):
        return (name in SCALAR_TYPES or name in ARRAY_TYPES or name in VECTOR_TYPES or name in self.structs
                or name in self.typedefs or name in QUALIFIERS)

    def field_type(self, type_, field):
        if type_ in self.structs:
            return self.structs[type_].field_type(field)
        if type_ in ("V3f", "V2f"):
            return "float"
        return None

    def return_type(self, name):
        return self.function_types.get(name)

    def lookup(self, name):
        for scope in reversed(self.scopes):
            if name in scope:
                py, type_ = scope[name]
                return Expr(py, ("name", py), type_)
        if self.self_struct is not None:
            ftype = self.self_struct.field_type(name)
            if ftype is not None:
                return Expr(f"self.{name}", ("attr", "self", name), ftype)
        if name in self.globals:
            py, type_ = self.globals[name]
            return Expr(py, ("name", py), type_)
        return None

    def declare_local(self, name, type_):
        py = py_name(name)
        taken = {p for scope in self.scopes for p, _ in scope.values()}
        if py in taken or name in self.globals:
            self.counter += 1
            py = f"{py}_{self.counter}"
        self.scopes[-1][name] = (py, type_)
        return py

    # --- output ------------------------------------------------------------------------
    def emit(self, text):
        """One Python line, ending with the L+C line it comes from (`#@12`), which error
        messages report."""
        line = self.tokens[self.pos - 1][2] if 0 < self.pos <= len(self.tokens) else 0
        self.lines.append("    " * self.indent + text + f"  #@{line}")

    def block_body(self, parse):
        """Runs `parse` one indent deeper, in a new scope; `pass` when it wrote nothing."""
        start = len(self.lines)
        self.indent += 1
        self.scopes.append({})
        parse()
        self.scopes.pop()
        if len(self.lines) == start:
            self.emit("pass")
        self.indent -= 1

    # --- types -------------------------------------------------------------------------
    def at_type(self):
        t = self.peek()
        if t[0] != "id" or not self.is_type_name(t[1]):
            return False
        if t[1] in self.structs or t[1] in VECTOR_TYPES or t[1] in self.typedefs or t[1] in ARRAY_TYPES:
            nxt = self.peek(1)
            return nxt[0] == "id" or nxt[1] in ("*", "&")
        return True

    def type_name(self):
        """Reads qualifiers and a type; returns 'int', 'float', 'bool', 'void', 'str', a vector
        or struct name."""
        type_ = None
        while True:
            t = self.peek()
            if t[0] != "id":
                break
            v = t[1]
            if v in QUALIFIERS:
                self.next()
                continue
            if v in SCALAR_TYPES:
                self.next()
                if not (type_ in ("float", "f32") and v == "int"):
                    type_ = SCALAR_TYPES[v] if type_ in (None, "int") else type_
                continue
            if type_ is None and (v in VECTOR_TYPES or v in self.structs or v in self.typedefs):
                self.next()
                type_ = VECTOR_TYPES.get(v) or self.typedefs.get(v) or v
                continue
            if type_ is None and v in ARRAY_TYPES:
                self.next()
                type_ = "float[]"
                continue
            break
        while self.peek()[1] in ("*", "&"):
            self.next()
        if type_ is None:
            raise self.error("expected a type")
        return type_

    def default_value(self, type_, dims):
        if dims:
            inner = self.default_value(type_, dims[1:])
            if type_ == "int" and len(dims) == 1 and self.char_array:
                return "''"
            return f"_array({dims[0]}, lambda: {inner})"
        if type_ == "int" or type_ == "bool":
            return "0"
        if type_ in ("float", "f32"):
            return "0.0"
        if type_ in ("V3f", "V2f") or type_ in self.structs:
            return f"{py_name(type_)}()"
        return "None"

    # --- declarations ------------------------------------------------------------------
    def declaration(self, is_global):
        """`type a = 1, b[3], c;` — one Python assignment per name."""
        self.char_array = self.at("char") or (self.at("const") and self.at("char", 1))
        array_type = ARRAY_TYPES.get(self.peek()[1])
        type_ = self.type_name()
        while True:
            while self.accept("*") or self.accept("&"):
                pass
            name = self.ident()
            dims = []
            while self.accept("["):
                dims.append("0" if self.at("]") else self.expression().code)
                self.expect("]")
            if array_type:
                type_, dims = "float", [str(array_type)] + dims
            full = type_ + "[]" * len(dims)
            if self.at("("):  # a constructor call: V3f p(1, 2, 3);
                args = self.arguments()
                value = f"{py_name(type_)}({', '.join(args)})"
            elif self.accept("="):
                value = self.initial_value(type_, dims)
            else:
                value = self.default_value(type_, dims)
            if is_global:
                py = py_name(name)
                self.globals[name] = (py, full)
            else:
                py = self.declare_local(name, full)
            self.emit(f"{py} = {value}")
            if not self.accept(","):
                break
        self.expect(";")

    def initial_value(self, type_, dims):
        e = self.assignment()
        if e.type == "init":
            struct = type_ if (type_ in self.structs or type_ in VECTOR_TYPES.values()) else None
            if dims:
                return f"_init_array({e.code}, {py_name(struct) if struct else 'None'})"
            if struct:
                return f"_init_struct({py_name(struct)}, {e.code})"
            return f"{e.code}.items[0]"
        if dims:
            return e.code
        return coerce(e.code, type_)

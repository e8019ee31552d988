"""The top level of an L+C file read into a `Model`: Python source for its C++ (globals,
structs, functions, production bodies, `Start:`/`End:` hooks, the axiom, the derivation
length) and plain data for its L-system (module declarations, productions with their
patterns, sections, groups, ignore/consider, maximum depths).
"""

from .control import BodyTranslator
from .cursor import SCALAR_TYPES
from .expressions import SCALARS, coerce, py_name
from .runtime import PREDEFINED_STRUCTS
from .statements import Struct

SECTIONS = {
    "production": "production", "productions": "production", "derivation": None,
    "decomposition": "decomposition", "interpretation": "interpretation",
    "homomorphism": "interpretation",
}
HOOKS = {"Start": "_start", "StartEach": "_start_each", "EndEach": "_end_each", "End": "_end"}


class Production:
    def __init__(self, section, group, left, left_new, pred, right, right_new, func, line):
        self.section = section
        self.group = group
        self.left = left  # [(name, arity)]
        self.left_new = left_new
        self.pred = pred
        self.right = right
        self.right_new = right_new
        self.func = func
        self.line = line


class Model:
    def __init__(self):
        self.modules = {}  # name -> [types]
        self.productions = []
        self.ignore = set()
        self.consider = None
        self.max_depth = {"decomposition": 1, "interpretation": 1}
        self.source = ""
        self.hooks = set()
        self.has_length = False
        self.ring = False
        self.last_line = 1
        self.gillespie = set()
        self.views = []  # vgroup names in order of appearance  # groups rewritten one reaction at a time (ggroup)


class Reader(BodyTranslator):
    def __init__(self, tokens, function_names):
        super().__init__(tokens)
        self.model = Model()
        self.section = "production"
        self.group = 0
        self.view = None  # the vgroup being read, by its number in order of appearance
        self.current_return = None
        for name in function_names:
            self.globals[name] = (py_name(name), "int")
        for name, cls in PREDEFINED_STRUCTS.items():
            struct = Struct(name)
            struct.fields = [(f, t, []) for f, t in zip(cls._fields, cls._types)]
            self.structs[name] = struct
        self.declare_views()

    def declare_views(self):
        """View names (`vgroup Name:`, `UseView(Name)`) are numbers lpfg gives each view."""
        views = []
        for k, t in enumerate(self.tokens):
            before = self.tokens[k - 2][1] if k >= 2 else ""
            if t[0] == "id" and (self.tokens[k - 1][1] == "vgroup" or before in ("UseView", "CloseView")):
                if t[1] not in views and t[1] not in self.globals:
                    views.append(t[1])
        for number, name in enumerate(views):
            self.globals[name] = (py_name(name), "int")
            self.lines.append(f"{py_name(name)} = {number}  #@{0}")

    def read(self):
        while self.peek()[0] != "eof":
            self.top_item()
        self.model.source = "\n".join(self.lines) + "\n"
        self.model.last_line = self.tokens[-1][2] if self.tokens else 1
        return self.model

    def top_item(self):
        t = self.peek()
        v = t[1]
        if self.accept(";"):
            return
        if t[0] == "id" and self.at(":", 1) and v in SECTIONS and SECTIONS[v]:
            self.next()
            self.next()
            self.section = SECTIONS[v]
            self.group = 0
            self.view = None
            return
        handler = {
            "module": self.module_declaration, "Axiom": self.axiom, "axiom": self.axiom,
            "ignore": self.ignore_list, "consider": self.ignore_list, "VerifyString": self.skip_statement,
            "struct": self.struct_or_declaration, "class": self.struct_or_declaration,
            "typedef": self.typedef, "using": self.skip_statement, "enum": self.enum,
            "group": self.group_start, "vgroup": self.group_start, "endgroup": self.group_end,
            "ggroup": self.group_start, "window": self.group_start,
            "endvgroup": self.group_end, "endwindow": self.group_end,
        }.get(v) if t[0] == "id" else None
        if handler:
            handler()
        elif v == "derivation" and self.at("length", 1):
            self.derivation_length()
        elif v == "ring" and self.at("L", 1):
            self.ring()
        elif v == "maximum" and self.at("depth", 1):
            self.maximum_depth()
        elif v in HOOKS and self.at(":", 1):
            self.hook()
        elif self.at_type() and not self._looks_like_production():
            self.declaration_or_function()
        elif t[0] == "id":
            self.production()
        else:
            raise self.error(f"unexpected '{v}' at the top level")

    def _looks_like_production(self):
        """`Name(x) :` or `A < B` are productions even when `Name` is also a type name."""
        t = self.peek()
        return t[1] in self.model.modules and self.at("(", 1)

    # --- L-system declarations ------------------------------------------------------------
    def module_declaration(self):
        self.next()
        while True:
            name = self.ident()
            types = []
            if self.accept("("):
                while not self.accept(")"):
                    types.append(self.type_name())
                    if self.peek()[0] == "id":  # a parameter name, allowed and ignored
                        self.next()
                    self.accept(",")
            self.model.modules[name] = types
            if self.accept("="):  # lpfg's own module numbers: module Cut() = 16;
                self.next()
            if not self.accept(","):
                break
        self.expect(";")

    def axiom(self):
        self.next()
        self.expect(":")
        modules = self.module_list(";")
        self.expect(";")
        self.emit("def _axiom():")
        self.emit(f"    {self.global_line()}")
        self.emit(f"    _np({', '.join(modules)})")

    def derivation_length(self):
        self.next()
        self.next()
        self.expect(":")
        e = self.expression()
        self.expect(";")
        self.model.has_length = True
        self.emit("def _derivation_length():")
        self.emit(f"    return _int({e.code})")

    def maximum_depth(self):
        self.next()
        self.next()
        self.expect(":")
        e = self.expression()
        self.expect(";")
        key = self.section if self.section != "production" else "decomposition"
        name = f"_max_depth_{key}"
        self.emit(f"def {name}():")
        self.emit(f"    return _int({e.code})")
        self.model.max_depth[key] = name  # evaluated once the model's globals exist

    def ring(self):
        """`ring L-system: 1;` — the string is a ring for contexts."""
        self.next()
        while not self.accept(":"):
            self.next()
        e = self.expression()
        self.expect(";")
        self.emit("def _ring():")
        self.emit(f"    return {e.code}")
        self.model.ring = True  # until _ring() says otherwise, after the model's globals exist

    def ignore_list(self):
        word = self.next()[1]
        self.expect(":")
        names = set()
        while not self.accept(";"):
            names.add(self.ident())
        if word == "ignore":
            self.model.ignore |= names
        else:
            self.model.consider = (self.model.consider or set()) | names

    def group_start(self):
        word = self.next()[1]
        t = self.next()
        self.expect(":")
        if word in ("vgroup", "window"):
            # a view's interpretation rules: lpfg draws each view in its own window
            if t[1] not in self.model.views:
                self.model.views.append(t[1])
            self.view = self.model.views.index(t[1])
        elif t[0] == "num":
            self.group = int(float(t[1].rstrip("fFlL")))
            if word == "ggroup":
                self.model.gillespie.add(self.group)

    def group_end(self):
        word = self.next()[1]
        self.accept(";")
        if word in ("endvgroup", "endwindow"):
            self.view = None
        else:
            self.group = 0

    def skip_statement(self):
        while not self.accept(";"):
            self.next()

    def enum(self):
        self.next()
        if self.peek()[0] == "id":
            self.next()
        self.expect("{")
        value = 0
        while not self.accept("}"):
            name = self.ident()
            if self.accept("="):
                value = self.ternary().code
            self.globals[name] = (py_name(name), "int")
            self.emit(f"{py_name(name)} = {value}")
            value = f"({value} + 1)"
            self.accept(",")
        self.accept(";")

    def hook(self):
        name = HOOKS[self.next()[1]]
        self.expect(":")
        self.model.hooks.add(name)
        self.function_body(name, [], None)

    def global_line(self):
        names = sorted({py for py, _ in self.globals.values()})
        return f"global {', '.join(names)}" if names else "pass"

    # --- productions ------------------------------------------------------------------------
    def production(self):
        start = self.peek()
        parts = {"left": [], "pred": [], "right": []}
        names = []
        where, left_new, right_new = "pred", False, False
        while not self.accept(":"):
            t = self.peek()
            if t[1] in ("<", "<<") and t[0] == "op":
                self.next()
                parts["left"], parts["pred"] = parts["pred"], []
                left_new = t[1] == "<<"
                continue
            if t[1] in (">", ">>") and t[0] == "op":
                self.next()
                where, right_new = "right", t[1] == ">>"
                continue
            if t[0] != "id":
                raise self.error(f"unexpected '{t[1] or 'end of file'}' in a production's predecessor", t)
            name = self.next()[1]
            formals = []
            if self.accept("("):
                while not self.accept(")"):
                    formals.append(self.ident())
                    self.accept(",")
            parts[where].append((name, len(formals)))
            types = self.model.modules.get(name, [])
            for k, formal in enumerate(formals):
                names.append((formal, types[k] if k < len(types) else _predefined_type(name)))
        if not parts["pred"]:
            raise self.error("a production needs a predecessor", start)
        func = f"_p{len(self.model.productions)}"
        self.model.productions.append(Production(
            self.section, self.group, parts["left"], left_new, parts["pred"],
            parts["right"], right_new, func, start[2]))
        self.model.productions[-1].view = self.view
        self.function_body(func, names, None)

    def function_body(self, name, params, return_type, method_of=None, initialisers=False):
        """`def name(params):` with the body that follows ('{…}' or one statement)."""
        self.scopes = [{}]
        saved_lines, self.lines = self.lines, []
        saved_indent, self.indent = self.indent, 1
        self.current_return = return_type
        self.self_struct = method_of
        py_params, entry = [], []
        for cname, type_, by_ref in [(p[0], p[1], p[2] if len(p) > 2 else False) for p in params]:
            py = self.declare_local(cname, type_)
            py_params.append(py)
            if type_ in SCALARS:
                entry.append(f"{py} = {coerce(py, type_)}")
            elif not by_ref:
                entry.append(f"{py} = _val({py})")
        for line in entry:
            self.emit(line)
        if initialisers and self.accept(":"):  # a constructor's `: field(value), …`
            while not self.at("{"):
                field = self.ident()
                self.expect("(")
                value = self.expression()
                self.expect(")")
                self.emit(f"self.{field} = {coerce(value.code, method_of.field_type(field))}")
                self.accept(",")
        if self.accept("{"):
            self.block_until_brace()
        else:
            self.statement()
        body, self.lines, self.indent = self.lines, saved_lines, saved_indent
        self.self_struct = None
        self.scopes = []
        head = ["self"] if method_of is not None else []
        self.emit(f"def {name}({', '.join(head + py_params)}):")
        self.emit(f"    {self.global_line()}")
        self.lines.extend("    " * self.indent + line for line in body)

    # --- C++ definitions ------------------------------------------------------------------
    def declaration_or_function(self):
        """A global variable, or a function (`type name(params) { … }`)."""
        k = 0
        while self.peek(k)[0] == "id" and (self.is_type_name(self.peek(k)[1]) or self.peek(k)[1] == "unsigned"):
            k += 1
        while self.peek(k)[1] in ("*", "&"):
            k += 1
        if self.peek(k)[0] == "id" and self.at("(", k + 1) and not self._is_constructor_call(k):
            self.function_definition()
        else:
            self.declaration(is_global=True)

    def _is_constructor_call(self, k):
        """`V3f p(1, 2, 3);` declares a variable: its parentheses hold values, not types."""
        nxt = self.peek(k + 2)
        if nxt[1] == ")":
            return self.at(";", k + 3)
        return nxt[0] != "id" or not self.is_type_name(nxt[1])

    def function_definition(self, method_of=None):
        return_type = self.type_name()
        name = self.ident()
        params = self.parameter_list()
        if self.accept(";"):  # a prototype
            self.function_types[name] = return_type
            return
        while self.peek()[0] == "id" and self.peek()[1] == "const":
            self.next()
        self.function_types[name] = return_type
        if method_of is None:
            self.globals.setdefault(name, (py_name(name), "function"))
        self.function_body(py_name(name), params, return_type, method_of)

    def parameter_list(self):
        self.expect("(")
        params = []
        if self.at("void") and self.at(")", 1):
            self.next()
        while not self.accept(")"):
            type_ = self.type_name()
            by_ref = self.tokens[self.pos - 1][1] == "&"
            name = self.ident() if self.peek()[0] == "id" else f"_arg{len(params)}"
            dims = 0
            while self.accept("["):
                while not self.accept("]"):
                    self.next()
                dims += 1
            if self.accept("="):
                raise self.error("default arguments are not supported")
            params.append((name, type_ + "[]" * dims, by_ref or dims > 0))
            self.accept(",")
        return params

    def struct_or_declaration(self):
        if self.peek(1)[0] == "id" and self.at("{", 2):
            self.next()
            name = self.ident()
            self.struct_definition(name)
            if not self.accept(";"):
                self.declaration_names_after_struct(name)
        elif self.at("{", 1):
            raise self.error("an unnamed struct outside a typedef is not supported")
        else:
            self.declaration_or_function()

    def declaration_names_after_struct(self, name):
        self.tokens.insert(self.pos, ("id", name, self.peek()[2], self.peek()[3]))
        self.declaration(is_global=True)

    def typedef(self):
        self.next()
        if self.at("struct") and (self.at("{", 1) or self.at("{", 2)):
            self.next()
            tag = self.ident() if self.peek()[0] == "id" else None
            name = tag or f"_Anon{len(self.structs)}"
            self.struct_definition(name)
            alias = self.ident()
            self.typedefs[alias] = name
            self.structs[alias] = self.structs[name]
            self.emit(f"{py_name(alias)} = {py_name(name)}")
            self.expect(";")
            return
        type_ = self.type_name()
        alias = self.ident()
        self.expect(";")
        self.typedefs[alias] = type_

    def struct_definition(self, name):
        struct = Struct(name)
        self.structs[name] = struct
        self.expect("{")
        methods = []
        while not self.accept("}"):
            if self.accept("public") or self.accept("private") or self.accept("protected"):
                self.expect(":")
                continue
            if self.at(name) and self.at("(", 1):
                methods.append(("ctor", self.pos))
                self._skip_member()
                continue
            if self.at("~"):
                self._skip_member()
                continue
            if self.at("enum"):
                self.enum_member(struct)
                continue
            k = 0
            while self.peek(k)[0] == "id" and self.is_type_name(self.peek(k)[1]):
                k += 1
            if self.peek(k)[0] == "id" and self.at("(", k + 1):
                methods.append(("method", self.pos))
                self._skip_member()
                continue
            type_ = self.type_name()
            while True:
                field = self.ident()
                dims = []
                while self.accept("["):
                    dims.append(self.expression().code)
                    self.expect("]")
                struct.fields.append((field, type_, dims))
                if not self.accept(","):
                    break
            self.expect(";")
        self.emit_struct(struct, methods)

    def enum_member(self, struct):
        """`enum { A, B } field;` inside a struct: the names are constants, the field an int."""
        self.next()
        if self.peek()[0] == "id":
            self.typedefs[self.next()[1]] = "int"
        self.expect("{")
        value = "0"
        while not self.accept("}"):
            name = self.ident()
            if self.accept("="):
                value = self.ternary().code
            self.globals[name] = (py_name(name), "int")
            self.emit(f"{py_name(name)} = {value}")
            value = f"({py_name(name)} + 1)"
            self.accept(",")
        while not self.accept(";"):
            name = self.ident()
            struct.fields.append((name, "int", []))
            self.accept(",")

    def _skip_member(self):
        depth = 0
        while True:
            t = self.next()
            if t[1] == "{":
                depth += 1
            elif t[1] == "}":
                depth -= 1
                if depth == 0:
                    self.accept(";")
                    return
            elif t[1] == ";" and depth == 0:
                return

    def emit_struct(self, struct, methods):
        cls = py_name(struct.name)
        self.emit(f"class {cls}(_Struct):")
        self.emit(f"    _fields = {tuple(f[0] for f in struct.fields)!r}")
        self.emit(f"    _types = {tuple(f[1] for f in struct.fields)!r}")
        defaults = ", ".join(f"lambda: {self.default_value(t, d)}" for _, t, d in struct.fields)
        self.emit(f"    _defaults = ({defaults}{',' if struct.fields else ''})")
        end = self.pos
        for kind, at in methods:
            self.pos = at
            saved, self.lines = self.lines, []
            if kind == "ctor":
                self.next()
                params = self.parameter_list()
                self.function_body(f"_ctor_{len(params)}", params, None, method_of=struct, initialisers=True)
            else:
                self.function_definition(method_of=struct)
            body, self.lines = self.lines, saved
            self.lines.extend("    " + line for line in body)
        self.pos = end


def _predefined_type(name):
    """The type of a parameter of a module the model does not declare (lpfg's own)."""
    if name in ("SetColor", "IncColor", "DecColor"):
        return "int"
    return "float" if name in TURTLE_FLOATS else None


TURTLE_FLOATS = {"F", "f", "Left", "Right", "Up", "Down", "RollL", "RollR", "SetWidth", "Sphere",
                 "Circle", "E1", "E2", "Surface", "MoveTo", "Line", "LineTo", "GetPos", "GetHead"}

"""C++ statements in L+C bodies: blocks, `if`, loops, `switch`, jumps, `produce`/`nproduce`,
and expression statements (assignments written as Python statements)."""

from .expressions import ASSIGN_OPS, Expr
from .statements import StatementTranslator
from .expressions import SCALARS


class BodyTranslator(StatementTranslator):
    def statement(self):
        t = self.peek()
        v = t[1]
        if t[0] == "op":
            if v == "{":
                self.next()
                self.block_until_brace()
                return
            if v == ";":
                self.next()
                return
        elif t[0] == "id":
            handler = {
                "if": self.if_statement, "while": self.while_statement, "for": self.for_statement,
                "do": self.do_statement, "switch": self.switch_statement,
                "break": self.break_statement, "continue": self.continue_statement,
                "return": self.return_statement, "produce": self.produce_statement,
                "nproduce": self.produce_statement, "propensity": self.propensity_statement,
            }.get(v)
            if handler:
                handler()
                return
            if v == "struct" and self.peek(1)[0] == "id" and self.peek(2)[0] == "id":
                self.declaration(is_global=False)
                return
            if v in ("typedef", "struct", "class", "enum", "goto", "new", "delete", "template"):
                raise self.error(f"'{v}' inside a body is not supported")
            if self.at_type():
                self.declaration(is_global=False)
                return
        self.expression_statement()

    def block_until_brace(self):
        """Statements up to the closing '}' (the '{' is read), in the current indent."""
        self.scopes.append({})
        while not self.accept("}"):
            if self.peek()[0] == "eof":
                raise self.error("missing '}'")
            self.statement()
        self.scopes.pop()

    def sub_statement(self):
        self.block_body(self.statement)

    def condition(self):
        self.expect("(")
        if self.at_type():  # if (int x = …) is rare; read as its value
            raise self.error("a declaration in a condition is not supported")
        e = self.expression()
        self.expect(")")
        return e.code

    def if_statement(self):
        self.next()
        self.emit(f"if {self.condition()}:")
        self.sub_statement()
        while self.at("else"):
            self.next()
            if self.at("if"):
                self.next()
                self.emit(f"elif {self.condition()}:")
                self.sub_statement()
            else:
                self.emit("else:")
                self.sub_statement()
                break

    def while_statement(self):
        self.next()
        self.emit(f"while {self.condition()}:")
        self.emit("    _tick()")
        self.loop_body(None)

    def loop_body(self, on_continue):
        self.loops.append(on_continue)
        self.sub_statement()
        self.loops.pop()

    def do_statement(self):
        self.next()
        self.emit("while True:")
        self.emit("    _tick()")
        # the test must run on `continue` too: read the body, then the test
        mark = len(self.lines)
        self.loops.append("__do__")
        self.sub_statement()
        self.loops.pop()
        self.expect("while")
        cond = self.condition()
        self.expect(";")
        test = f"if not {cond}: break"
        self.lines[mark:] = [line.replace("__do_continue__", test) for line in self.lines[mark:]]
        self.emit("    " + test)

    def for_statement(self):
        self.next()
        self.expect("(")
        self.scopes.append({})
        if not self.accept(";"):
            if self.at_type():
                self.declaration(is_global=False)
            else:
                self.expression_statement()
        cond = "True" if self.at(";") else self.expression().code
        self.expect(";")
        step_lines = []
        if not self.at(")"):
            saved, self.lines = self.lines, []
            saved_indent, self.indent = self.indent, 0
            self.simple_statement(self.expression_parts())
            step_lines, self.lines, self.indent = self.lines, saved, saved_indent
        self.expect(")")
        self.emit(f"while {cond}:")
        self.emit("    _tick()")
        self.loops.append(step_lines)
        start = len(self.lines)
        self.sub_statement()
        self.loops.pop()
        pad = "    " * (self.indent + 1)
        body = self.lines[start:]
        if body == [pad + "pass"]:
            self.lines[start:] = []
        for line in step_lines:
            self.lines.append(pad + line)
        self.scopes.pop()

    def switch_statement(self):
        self.next()
        self.expect("(")
        value = self.expression().code
        self.expect(")")
        self.expect("{")
        self.counter += 1
        sw, fell = f"_sw{self.counter}", f"_fell{self.counter}"
        self.emit(f"{sw} = {value}")
        self.emit(f"{fell} = False")
        self.emit("while True:")
        self.indent += 1
        self.loops.append("__switch__")
        self.scopes.append({})
        while not self.accept("}"):
            if self.accept("case"):
                label = self.ternary().code
                self.expect(":")
                self.emit(f"if {fell} or {sw} == {label}: {fell} = True")
            elif self.accept("default"):
                self.expect(":")
                self.emit(f"{fell} = True")
            else:
                self.emit(f"if {fell}:")
                self.block_body(self.statement)
        self.scopes.pop()
        self.loops.pop()
        self.emit("break")
        self.indent -= 1

    def break_statement(self):
        self.next()
        self.expect(";")
        self.emit("break")

    def continue_statement(self):
        self.next()
        self.expect(";")
        for kind in reversed(self.loops):
            if kind == "__switch__":
                raise self.error("'continue' inside a switch is not supported")
            if kind == "__do__":
                self.emit("__do_continue__")
            elif kind:
                for line in kind:
                    self.emit(line)
            break
        self.emit("continue")

    def return_statement(self):
        self.next()
        if self.accept(";"):
            self.emit("return None")
            return
        e = self.expression()
        self.expect(";")
        kind = self.current_return
        if kind in SCALARS:
            from .expressions import coerce
            self.emit(f"return {coerce(e.code, kind)}")
        else:
            self.emit(f"return {e.code}")

    def produce_statement(self):
        word = self.next()[1]
        modules = self.module_list(";")
        self.expect(";")
        if modules:
            self.emit(f"_np({', '.join(modules)})")
        if word == "produce":
            self.emit("return _PRODUCED")

    def propensity_statement(self):
        """`propensity p produce …;` in a ggroup: the reaction's rate, then its successor."""
        self.next()
        rate = self.ternary().code
        self.emit(f"_propensity({rate})")
        self.produce_statement()

    def module_list(self, end):
        """`A(x, y) SB B EB …` up to `end`: Python tuples ('A', (x, y))."""
        modules = []
        while not self.at(end):
            name = self.ident()
            args = self.arguments() if self.at("(") else []
            inside = "".join(a + ", " for a in args)
            modules.append(f"({name!r}, ({inside}))")
        return modules

    def expression_parts(self):
        """An expression, or an assignment split as (target, operator, value)."""
        left = self.ternary()
        t = self.peek()
        if t[0] == "op" and t[1] in ASSIGN_OPS and left.lv is not None:
            self.next()
            return (left, t[1], self.assignment())
        while self.accept(","):
            self.simple_statement(left)
            left = self.assignment()
        return left

    def simple_statement(self, parts):
        if isinstance(parts, Expr):
            self.emit(parts.code)
            return
        left, op, right = parts
        if left.lv[0] == "name":
            self.emit(f"{left.code} = {self.assign_value(left, op, right)}")
        else:
            self.emit(self.assign_code(left, op, right, as_value=False))

    def expression_statement(self):
        if self.at("sprintf") and self.at("(", 1):
            self.next()
            self.next()
            target = self.postfix()
            self.expect(",")
            rest = []
            while not self.accept(")"):
                rest.append(self.assignment().code)
                self.accept(",")
            self.expect(";")
            self.emit(f"{target.code} = _sprintf({', '.join(rest)})")
            return
        parts = self.expression_parts()
        self.simple_statement(parts)
        while self.accept(","):
            self.simple_statement(self.expression_parts())
        self.expect(";")

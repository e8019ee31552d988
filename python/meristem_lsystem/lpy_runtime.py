"""Running an L-Py model: its Python executed once, then the derivation, as L-Py does it.

Order (L-Py's lsystem.cpp): the INITIALISATION section runs and `__initialiseContext__(context)`
sets materials, panel scalars, curves and functions; the model's code runs (rules are functions
in its namespace); `Start()`; each step `StartEach()`, productions of the active group (and
group 0), decompositions up to their maximum depth, `EndEach(lstring)` (a returned string
replaces the current one), and `Stop()` ends the loop; `End(lstring)`; then interpretation
rules (homomorphism) up to their maximum depth give the string the turtle draws."""

from __future__ import annotations

import inspect
import random
import time

from .lpy_context import Context
from .lpy_errors import LimitReached, ModelError, from_exception
from .lpy_lstring import LpySyntaxError
from .lpy_match import ContextFilter, Pattern, match_left, match_pred, match_right
from .lpy_source import translate
from .lstring import Lstring, Module, StringReader, make_module, predefined_names, to_modules
from . import plantgl_modules


def compile_quietly(code: str, filename: str):
    """Compiles the model's Python; its SyntaxWarnings (`is` with a literal …) are not ours."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return compile(code, filename, "exec")


class Rule:
    __slots__ = ("spec", "func", "order", "pred", "left", "right", "new_left", "new_right",
                 "first", "group", "simple", "nargs")

    def __init__(self, spec, func, order, consts):
        self.spec, self.func, self.order, self.group = spec, func, order, spec.group
        def compile_(pats):
            return [Pattern(p.name, [(k, compile_(v) if k == "repeat" else consts(k, v)) for k, v in p.specs])
                    for p in pats]

        self.pred, self.left, self.right = compile_(spec.pred), compile_(spec.left), compile_(spec.right)
        self.new_left, self.new_right = compile_(spec.new_left), compile_(spec.new_right)
        self.first = self.pred[0].name
        # one predecessor module, plain parameters, no context: matched by a length test
        only = self.pred[0]
        self.nargs = only.nfixed
        self.simple = (len(self.pred) == 1 and not (self.left or self.right or self.new_left or self.new_right)
                       and only.name != "*" and all(k == "var" for k, _ in only.specs))


class LpyRuntime:
    """One model: load (translate + execute), derive, interpret."""

    def __init__(self, files: dict[str, str], main: str, options: dict, parameters=None):
        self.files, self.main, self.options = files, main, options
        self.filename = main
        self.namespace: dict = {}
        self.context = Context(self)
        self.iteration = 0
        self.group = 0
        self.forward_dir = True
        self.stop_requested = False
        self.nbuf: list = []
        self.deadline = time.monotonic() + float(options.get("time_limit", 50))
        self.max_modules = int(options.get("max_modules", 2_000_000))
        self.parameters = dict(parameters or {})
        self.notes: list[dict] = []
        self._api = None
        self.rules: dict[str, list[Rule]] = {}
        self._tables: dict = {}

    # ----- the model's view of its L-system -----
    def api(self) -> dict:
        if self._api is None:
            self._api = self._make_api()
        return self._api

    def _make_api(self) -> dict:
        rt = self

        def extern(**kw):
            for name, value in kw.items():
                rt.namespace.setdefault(name, rt.parameters.get(name, value))

        def nproduce(value):
            rt.nbuf.extend(to_modules(value))

        return {
            "__M": make_module, "__Mcopy": lambda m: m.copy() if isinstance(m, Module) else to_modules(m)[0], "__Mstar": lambda name, *args: Module(name, list(args)),
            "__produce": lambda mods: mods, "__nproduce": rt.nbuf_extend,
            "nsproduce": nproduce, "pproduce": nproduce,
            "getIterationNb": lambda: rt.iteration, "execContext": lambda: rt.context, "Stop": rt.stop, "stop": rt.stop,
            "forward": lambda: rt.set_direction(True), "backward": lambda: rt.set_direction(False),
            "isForward": lambda: rt.forward_dir, "useGroup": rt.use_group,
            "getGroup": lambda: rt.group, "context": lambda: rt.context,
            "extern": extern, "frameDisplay": lambda *a: None, "isAnimationEnabled": lambda: False,
            "Lsystem": rt.sub_lsystem, "xrange": range, "unicode": str, "long": int,
            "getDerivationLength": lambda: rt.derivation_length,
            "open": rt.open_file, "requestSelection": rt.request_selection,
        }

    def open_file(self, name, mode="r", *args, **kw):
        """The model's `open`: its own files from `files` (read); writes are kept nowhere."""
        import io

        base = str(name).replace("\\", "/").split("/")[-1]
        if any(c in mode for c in "wax+"):
            self.note(f"the model writes '{base}': Meristem keeps no files (the text is dropped)")
            return io.StringIO()
        if base not in self.files:
            raise FileNotFoundError(f"no file '{base}' came with the model")
        return io.StringIO(self.files[base])

    def request_selection(self, *args):
        self.note("interactive selection is not available: the model continues without one")

    def note(self, message: str):
        """A note at the model's line that is running now."""
        import sys

        line, frame = 0, sys._getframe(1)
        while frame is not None:
            if frame.f_code.co_filename == self.filename:
                line = frame.f_lineno
                break
            frame = frame.f_back
        if not any(n["message"] == message for n in self.notes):
            self.notes.append({"line": line, "message": message})

    def read_string(self, text: str) -> list:
        """A module string given as text while the model runs: its parameters are evaluated
        in the model's namespace (they are the model's own expressions)."""
        from .lpy_lstring import to_python

        return eval(to_python(text, self.source.names), self.namespace)

    def nbuf_extend(self, mods):
        self.nbuf.extend(mods)

    def axiom_value(self, ax):
        self.nbuf.clear()
        value = ax()
        got = self.nbuf + (to_modules(value) if value is not None else [])
        self.nbuf.clear()
        return got

    def stop(self):
        self.stop_requested = True

    def set_direction(self, forward: bool):
        self.forward_dir = forward

    def use_group(self, group):
        self.group = int(group)

    def sub_lsystem(self, filename, parameters=None):
        from .lpy_compose import SubLsystem

        return SubLsystem(self, filename, parameters)

    # ----- loading -----
    def load(self):
        text = self.files[self.main]
        try:
            self.source = translate(text, predefined_names())
        except LpySyntaxError as e:
            raise ModelError(f"SyntaxError: {e.message}", e.line, e.column) from None
        src = self.source
        self.notes.extend(src.notes)
        StringReader.current = self.read_string
        Module.named.update({name: {p: i for i, p in enumerate(params)}
                             for name, params in src.declared.items() if params})
        ns = self.namespace
        ns.update({"__name__": "__lpy__", "__builtins__": __builtins__})
        ns.update(plantgl_modules.plantgl_names())
        ns.update(plantgl_modules.lpy_names())
        ns.update(self.api())
        ns.update(self.parameters)
        plantgl_modules.install({"Lsystem": self.sub_lsystem})
        try:
            if src.init_code is not None:
                exec(compile_quietly(src.init_code, self.filename), ns)
                init = ns.get("__initialiseContext__")
                if init:
                    init(self.context)
            exec(compile_quietly(src.code, self.filename), ns)
            for name, value in self.parameters.items():
                ns[name] = value
            self._build_rules()
        except LimitReached:
            raise
        except Exception as e:  # the model's own code failed
            raise from_exception(e, self.filename) from None

    def _build_rules(self):
        def consts(kind, value):
            # the model's own expressions: a constant, or a test on a parameter
            if kind == "const":
                return eval(value, self.namespace)
            if kind == "cond":
                return eval(f"lambda {value[0]}: {value[1]}", self.namespace)
            return value

        self.all_rules = []
        for order, spec in enumerate(self.source.rules):
            self.all_rules.append(Rule(spec, self.namespace[spec.function], order, consts))
        self.filt = ContextFilter(self.source.ignore, self.source.consider)

    @property
    def derivation_length(self) -> int:
        steps = self.options.get("steps")
        if steps is not None:
            return int(steps)
        # L-Py's default derivation length is 1 (lsystem.cpp: __max_derivation(1))
        return int(self.namespace.get("__derivation_length__", 1) or 0)

    def axiom(self) -> Lstring:
        ax = self.namespace.get("__axiom__", [])
        if callable(ax):
            ax = self.axiom_value(ax)
        return Lstring(to_modules(ax))

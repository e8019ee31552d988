"""lpfg's L+C run in Python: `run(files, main, options)` with the contract of
`meristem_lsystem.run` (see `python/README.md`).

Stages, one module each: `preprocess` (the C preprocessor) → `reader` (the L+C top level, with
`control`/`statements`/`expressions` translating C++ into Python source) → the source compiled
and run in a namespace from `runtime` → `derive` (lpfg's derivation, with `matching` for
contexts) → `output` (the string in lpfg's module names).
"""

import re
import sys

from .derive import Engine
from .environment import environment_of
from .lexer import LpfgError
from .output import write_lstring
from .preprocess import preprocess
from .reader import Reader
from .runtime import Runtime

_LINE = re.compile(r"#@(\d+)$")

# lpfg modules that ask the environment for values it fills in between steps (the turtle's
# queries, GetPos and kin, are answered: turtle.py).
QUERIES = {"E1": "environment", "E2": "environment", "EA20": "environment"}


def run(files, main, options=None):
    options = options or {}
    notes = []
    result = {"ok": False, "dialect": "lpfg", "steps": 0, "lstring": "", "materials": [],
              "notes": notes, "error": None, "objects": []}
    runtime = None
    engine = None
    source_lines = []
    try:
        runtime = Runtime(files, options.get("seed", 0) or 0, float(options.get("time_limit", 50.0)), notes)
        tokens = preprocess(files, main, notes)
        model = Reader(tokens, runtime.functions.names).read()
        source_lines = model.source.split("\n")
        runtime.source_lines = source_lines
        ns = runtime.namespace()
        for name, number in runtime.functions.names.items():
            ns[name] = number
        code = compile(model.source, "<lpfg>", "exec")
        exec(code, ns)  # the model's own code, translated
        environment = environment_of(files, notes)
        engine = Engine(model, ns, runtime, int(options.get("max_modules", 2_000_000)), environment)
        final, steps = engine.run(options.get("steps"))
        result["steps"] = steps
        result["lstring"] = write_lstring(final, notes)
        result["ok"] = True
        if environment is None:
            _note_queries(final, notes)
        if len(model.views) > 1:
            notes.append({"line": 0, "message": f"lpfg draws each view in its own window; here the first, "
                          f"{model.views[0]}, is drawn (not {', '.join(model.views[1:])})"})
        if any(m[0] == "Terrain" for m in final):
            notes.append({"line": 0, "message": "Terrain: lpfg's terrain (from its own terrain files and camera) is not reproduced"})
    except LpfgError as e:
        line = e.line or _model_line(sys.exc_info()[2], source_lines) or (engine.current_line if engine else 0)
        result["error"] = {"line": line, "column": e.column, "message": e.message}
    except RecursionError:
        result["error"] = {"line": engine.current_line if engine else 0, "column": 0,
                           "message": "recursion too deep in the model's functions"}
    except Exception as e:  # the model's own code failing at run time
        line = _model_line(sys.exc_info()[2], source_lines) or (engine.current_line if engine else 0)
        result["error"] = {"line": line, "column": 0, "message": _describe(e)}
    return result


def _model_line(tb, source_lines):
    line = 0
    while tb is not None:
        if tb.tb_frame.f_code.co_filename == "<lpfg>":
            k = tb.tb_lineno - 1
            if 0 <= k < len(source_lines):
                m = _LINE.search(source_lines[k])
                if m:
                    line = int(m.group(1))
        tb = tb.tb_next
    return line


def _describe(e):
    if isinstance(e, NameError):
        name = getattr(e, "name", None) or str(e)
        return f"'{name}' is not defined (not a variable, function or lpfg call this runtime knows)"
    if isinstance(e, ZeroDivisionError):
        return "division by zero"
    return f"{type(e).__name__}: {e}"


def _note_queries(final, notes):
    seen = {m[0] for m in final if m[0] in QUERIES}
    for name in sorted(seen):
        kind = QUERIES[name]
        notes.append({"line": 0, "message": f"{name}: lpfg fills its parameters from the {kind} between steps; "
                      "here they keep the values the productions gave them"})

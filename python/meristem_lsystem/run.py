"""The package's one entry point: `run(files, main, options)` → a JSON-serialisable result.

The dialect follows `main`'s extension (`.lpy` → L-Py; `.l` → lpfg's L+C) unless
`options["dialect"]` says otherwise. Limits: `max_modules` after each step, `time_limit` at each
rule application, and (CPython's main thread) an interval timer that stops a model's own
endless loop; in Pyodide the worker running it is the last resort."""

from __future__ import annotations

import contextlib
import io
import random
import signal
import threading

from .lpy_errors import LimitReached, from_exception
from .lstring import Module, ObjectTable, format_lstring

MAX_OUTPUT = 20_000  # characters of what the model printed, kept in result["output"]
DEFAULTS = {"steps": None, "seed": 0, "max_modules": 2_000_000, "time_limit": 50.0}


def dialect_of(files: dict, main: str, options: dict) -> str:
    if options.get("dialect"):
        return options["dialect"]
    return "lpfg" if main.endswith(".l") else "lpy"


def empty_result(dialect: str) -> dict:
    return {"ok": False, "dialect": dialect, "steps": 0, "lstring": "", "materials": [],
            "notes": [], "error": None, "objects": []}


def run(files: dict, main: str, options: dict | None = None) -> dict:
    options = {**DEFAULTS, **(options or {})}
    dialect = dialect_of(files, main, options)
    if dialect == "lpy":
        runner = run_lpy
    else:
        try:
            from .lpfg_run import run_lpfg as runner  # the lpfg dialect (its own module)
        except ImportError:
            result = empty_result(dialect)
            result["error"] = {"line": 0, "column": 0, "message": "the lpfg dialect is not available"}
            return result
    if main not in files:
        result = empty_result(dialect)
        result["error"] = {"line": 0, "column": 0, "message": f"no file named {main!r}"}
        return result
    printed = io.StringIO()
    with Alarm(float(options["time_limit"]) + 2.0), contextlib.redirect_stdout(printed):
        result = runner(files, main, options)
    text = printed.getvalue()
    result["output"] = text if len(text) <= MAX_OUTPUT else text[:MAX_OUTPUT] + "\n…"
    return result


class Alarm:
    """Raises LimitReached in the main thread when `seconds` pass (where signals exist)."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.active = hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()

    def _fire(self, signum, frame):
        raise LimitReached(f"the model ran past the time limit ({self.seconds - 2:g} s)")

    def __enter__(self):
        if self.active:
            try:
                self.previous = signal.signal(signal.SIGALRM, self._fire)
                signal.setitimer(signal.ITIMER_REAL, self.seconds)
            except Exception:  # Pyodide and others without working timers: the worker's limit
                self.active = False
        return self

    def __exit__(self, *exc):
        if self.active:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, self.previous)
        return False


def run_lpy(files: dict, main: str, options: dict) -> dict:
    from .lpy_derive import derive, interpret
    from .lpy_runtime import LpyRuntime
    from .turtle_guide import expand_guides

    result = empty_result("lpy")
    random.seed(options.get("seed", 0))
    Module.named.clear()  # named parameters are the declarations of this run's files
    rt = LpyRuntime(files, main, options)
    table = ObjectTable()
    try:
        rt.load()
        s = derive(rt)
        result["steps"] = rt.steps_done
        s = expand_guides(interpret(rt, s), rt.note)
        ObjectTable.current = table
        result["lstring"] = format_lstring(s)
        result["ok"] = True
    except LimitReached as e:
        result["error"] = {"line": 0, "column": 0, "message": str(e)}
    except Exception as e:  # the model's own code, a rule body, or a ModelError located here
        result["error"] = from_exception(e, main).as_dict()
    except SystemExit as e:  # the model called exit(): an error at its line, not the end of ours
        error = from_exception(e, main)
        error.message = "the model called exit()"
        result["error"] = error.as_dict()
    finally:
        ObjectTable.current = None
    result["objects"] = table.objects
    result["materials"] = [{"index": i, "rgb": m.rgb()} for i, m in sorted(rt.context.turtle.materials.items())]
    if rt.context.turtle.settings:
        result["turtle"] = dict(rt.context.turtle.settings)
    result["notes"] = rt.notes
    return result

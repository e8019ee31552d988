"""Helpers for the lpfg tests: run an L+C text, read the result back as modules."""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from meristem_lsystem import run  # noqa: E402

_MODULE = re.compile(r"([A-Za-z_][A-Za-z_0-9]*)\(([^()]*)\)")


def run_lpfg(source, extra=None, **options):
    files = {"lsystem.l": source}
    files.update(extra or {})
    return run(files, "lsystem.l", options)


def modules(result):
    """The final string as [(name, [values as text])]."""
    assert result["ok"], result["error"]
    return [(m.group(1), [v for v in m.group(2).split(",") if v]) for m in _MODULE.finditer(result["lstring"])]


def count(result, name):
    return sum(1 for n, _ in modules(result) if n == name)


def values(source, module="F"):
    """The parameters of every `module` in the final string of `source`, as floats."""
    return [float(args[0]) for n, args in modules(run_lpfg(source)) if n == module]


def axiom_of(body, declarations=""):
    """A model whose Start: runs `body` (C++) and whose axiom writes F(result)."""
    return f"""#include <lpfgall.h>
{declarations}
float result;
derivation length: 0;
Start: {{ {body} }}
Axiom: F(result);
"""

"""Shared by the L-Py tests: run a model given as text, count modules of its string."""

from __future__ import annotations

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))

from meristem_lsystem import run  # noqa: E402

REPO = os.path.dirname(os.path.dirname(HERE))
COLLECTIONS = [os.path.join(REPO, "crate", "tests", "collections", "lpy")]


def run_text(text: str, **options) -> dict:
    return run({"model.lpy": text}, "model.lpy", options)


def count(lstring: str, name: str) -> int:
    """How many modules named `name` the string holds, read as L-Py reads it."""
    from meristem_lsystem.lpy_lstring import NameTable, parse_modules
    from meristem_lsystem.lstring import predefined_names

    return sum(1 for m in parse_modules(lstring, NameTable(predefined_names())) if m.name == name)


def collection_file(source_path: str) -> tuple[str, str] | None:
    """(name, text) of an L-Py collection file by its path in L-Py's repository, if copied."""
    flat = source_path.replace("/", "--")
    for folder in COLLECTIONS:
        if not os.path.isdir(folder):
            continue
        for root, _, names in os.walk(folder):
            for name in names:
                path = os.path.join(root, name)
                if name == flat or path.endswith(source_path):
                    with open(path, encoding="utf-8", errors="replace") as f:
                        return name, f.read()
    return None

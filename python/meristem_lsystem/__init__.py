"""Runs L-Py models (and, behind the same entry point, lpfg's L+C) in plain Python.

`run(files, main, options)` is the only entry point; see python/README.md for the result."""

from .run import run

__all__ = ["run"]

"""Errors of a model run, each with the model's line (never a line of this package)."""

from __future__ import annotations

import traceback


class ModelError(Exception):
    """An error to report: message, line and column in the model's main file."""

    def __init__(self, message: str, line: int = 0, column: int = 0):
        super().__init__(message)
        self.message, self.line, self.column = message, line, column

    def as_dict(self) -> dict:
        return {"line": self.line, "column": self.column, "message": self.message}


class LimitReached(Exception):
    """The string grew past `max_modules` or the run passed `time_limit`."""


def from_exception(exc: BaseException, filename: str) -> ModelError:
    """A Python exception raised while the model ran, located at the model's deepest line."""
    if isinstance(exc, SyntaxError) and exc.filename == filename:
        return ModelError(f"SyntaxError: {exc.msg}", exc.lineno or 0, exc.offset or 0)
    line = 0
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        if frame.f_code.co_filename == filename:
            line = lineno
    if isinstance(exc, ModelError):
        if not exc.line:
            exc.line = line
        return exc
    text = f"{type(exc).__name__}: {exc}"
    if isinstance(exc, (ImportError, ModuleNotFoundError)):
        text += " (Meristem runs models with Python's standard library and PlantGL's names only)"
    return ModelError(text, line, 0)

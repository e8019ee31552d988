"""The lpfg dialect behind `run`: the package `lpfg/` (L+C read, translated and derived)."""

from .lpfg import run as run_lpfg

__all__ = ["run_lpfg"]

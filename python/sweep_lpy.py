"""Dev script: runs every .lpy of a folder (default crate/tests/collections/lpy) and counts the models
whose run is ok and whose string draws something. `python3 python/sweep_lpy.py [DIR] [-v]`."""

from __future__ import annotations

import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from meristem_lsystem import run  # noqa: E402

DRAWING = {"F", "nF", "@O", "@o", "@B", "@b", "~", "LineTo", "OLineTo", "LineRel", "OLineRel", "@g",
           "Sweep", "surface", "Frame", "Arrow", "@Gc", "{"}


def draws(lstring: str) -> bool:
    """Whether the string holds a module that draws (read as L-Py reads it)."""
    from meristem_lsystem.lpy_lstring import NameTable, parse_modules
    from meristem_lsystem.lstring import predefined_names

    if len(lstring) > 200_000:
        # long strings: the first 200 000 characters tell (drawing starts early in a plant)
        lstring = lstring[:200_000].rsplit(")", 1)[0] + ")"
    try:
        return any(m.name in DRAWING for m in parse_modules(lstring, NameTable(predefined_names())))
    except Exception:
        return False


def files_for(folder: str, name: str) -> dict:
    """The model plus every other .lpy of the folder under its original base name."""
    files = {}
    for other in os.listdir(folder):
        if other.endswith(".lpy"):
            with open(os.path.join(folder, other), encoding="utf-8", errors="replace") as f:
                files[other.split("--")[-1]] = f.read()
    with open(os.path.join(folder, name), encoding="utf-8", errors="replace") as f:
        files[name] = f.read()
    return files


def main():
    folder = next((a for a in sys.argv[1:] if not a.startswith("-")), os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "crate", "tests", "collections", "lpy"))
    verbose = "-v" in sys.argv
    names = sorted(n for n in os.listdir(folder) if n.endswith(".lpy"))
    good = 0
    failures = []
    for name in names:
        t0 = time.monotonic()
        result = run(files_for(folder, name), name, {"time_limit": 50})
        dt = time.monotonic() - t0
        drawn = draws(result["lstring"])
        if result["ok"] and drawn:
            good += 1
        else:
            why = result["error"]["message"] if result["error"] else "draws nothing"
            line = result["error"]["line"] if result["error"] else 0
            failures.append((name, line, why[:150], dt))
        if verbose:
            print(f"{dt:6.2f}s {'ok ' if result['ok'] and drawn else 'BAD'} {name}", flush=True)
    for name, line, why, dt in failures:
        print(f"FAIL {name}:{line}: {why} ({dt:.1f}s)")
    print(f"{good} of {len(names)} build a plant")


if __name__ == "__main__":
    main()

"""Dev script: runs every lpfg object of a folder (default crate/tests/collections/lpfg; one vlab
object per sub-folder) and counts those whose run is ok and whose string draws something.
`python3 python/sweep_lpfg.py [DIR] [-v]`."""

from __future__ import annotations

import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from meristem_lsystem import run  # noqa: E402
from meristem_lsystem.lpfg.__main__ import read_object  # noqa: E402

# lpfg's modules that draw (a Terrain needs its terrain files; Label alone is no plant).
DRAWING = re.compile(r"(?<![A-Za-z_0-9])(F|Line|LineTo|LineTo2f|LineTo3f|LineTo3d|LineRel|Line2f|"
                     r"Line3f|Circle|Sphere|Surface|Surface3|BSurface|Cylinder|SP|Rhombus|"
                     r"Triangle|Mesh)\(")


def main():
    folder = next((a for a in sys.argv[1:] if not a.startswith("-")), os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "crate", "tests", "collections", "lpfg"))
    verbose = "-v" in sys.argv
    names = sorted(n for n in os.listdir(folder) if os.path.isdir(os.path.join(folder, n)))
    good = 0
    failures = []
    for name in names:
        files, main_file = read_object(os.path.join(folder, name))
        t0 = time.monotonic()
        result = run(files, main_file, {"time_limit": 50})
        dt = time.monotonic() - t0
        draws = result["ok"] and bool(DRAWING.search(result["lstring"]))
        good += draws
        if not draws:
            error = result["error"]
            why = error["message"] if error else "draws nothing: " + "; ".join(n["message"] for n in result["notes"])
            failures.append((name, error["line"] if error else 0, why[:160], dt))
        if verbose:
            print(f"{dt:6.2f}s {'ok ' if draws else 'BAD'} {name}", flush=True)
    for name, line, why, dt in failures:
        print(f"FAIL {name}:{line}: {why} ({dt:.1f}s)")
    print(f"{good} of {len(names)} build a plant")


if __name__ == "__main__":
    main()

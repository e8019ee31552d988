"""`python3 -m meristem_lsystem.lpfg FOLDER|FILE.l [--steps N] [--seed S]` prints `run`'s JSON."""

import argparse
import contextlib
import io
import json
import os

from . import run


def read_object(path):
    """A vlab object's text files (name -> text), and the L+C file to run."""
    if os.path.isfile(path):
        folder, main = os.path.dirname(path) or ".", os.path.basename(path)
    else:
        folder, main = path, None
    files = {}
    for name in sorted(os.listdir(folder)):
        full = os.path.join(folder, name)
        if not os.path.isfile(full) or os.path.getsize(full) > 4_000_000:
            continue
        try:
            with open(full, encoding="utf-8", errors="replace") as f:
                text = f.read()
        except OSError:
            continue
        if "\0" in text:
            continue
        files[name] = text
    if main is None:
        main = main_of(files)
    return files, main


def main_of(files):
    """The L+C file the object's `specifications` runs with lpfg, else its only `.l` file."""
    spec = files.get("specifications", "")
    for line in spec.splitlines():
        words = line.split()
        if words and words[0] == "lpfg":
            for w in words[1:]:
                if w.endswith(".l") and w in files:
                    return w
    ls = [n for n in files if n.endswith(".l")]
    return "lsystem.l" if "lsystem.l" in ls else (ls[0] if ls else "lsystem.l")


def main():
    parser = argparse.ArgumentParser(prog="meristem_lsystem.lpfg")
    parser.add_argument("path")
    parser.add_argument("--steps", type=int, default=None)
    parser.add_argument("--seed", type=int, default=0)
    a = parser.parse_args()
    files, main_file = read_object(a.path)
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):  # what the model prints stays out of the JSON
        result = run(files, main_file, {"steps": a.steps, "seed": a.seed})
    result["output"] = printed.getvalue()[:100_000]
    print(json.dumps(result))


if __name__ == "__main__":
    main()

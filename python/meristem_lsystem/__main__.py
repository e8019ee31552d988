"""`python3 -m meristem_lsystem FILE [--steps N] [--seed S]`: prints run()'s JSON.

FILE is an .lpy (the other files of its folder come along, for `Lsystem('x.lpy')`) or a vlab
object's folder (its `specifications` names the L-system file)."""

from __future__ import annotations

import argparse
import json
import os
import sys

from .run import run

TEXT_EXTENSIONS = (".lpy", ".l", ".h", ".v", ".func", ".a", ".map", ".mat", ".txt", ".py",
                   ".s", ".con", ".crv", ".fset", ".cset", ".e", ".in", "specifications",
                   ".spec", ".tset", ".vset")  # lpfg: environment specs, timelines, values


def read_folder(folder: str) -> dict:
    files = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if os.path.isfile(path) and name.endswith(TEXT_EXTENSIONS) and os.path.getsize(path) < 4_000_000:
            with open(path, encoding="utf-8", errors="replace") as f:
                files[name] = f.read()
    return files


def main_of_object(files: dict) -> str | None:
    spec = files.get("specifications", "")
    for token in spec.split():
        if token.endswith(".l") and token in files:
            return token
    return next((n for n in files if n.endswith(".l")), None)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m meristem_lsystem")
    parser.add_argument("file")
    parser.add_argument("--steps", type=int, default=None)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    if os.path.isdir(args.file):
        files = read_folder(args.file)
        main_name = main_of_object(files)
        if main_name is None:
            print(json.dumps({"ok": False, "error": {"line": 0, "column": 0,
                                                     "message": "no L-system file in the folder"}}))
            return 1
    else:
        files = read_folder(os.path.dirname(os.path.abspath(args.file)))
        main_name = os.path.basename(args.file)
        with open(args.file, encoding="utf-8", errors="replace") as f:
            files[main_name] = f.read()
    result = run(files, main_name, {"steps": args.steps, "seed": args.seed})
    print(json.dumps(result))
    return 0 if result.get("ok") else 1


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Copies two public collections, whole and unselected, into this folder (issue 49's corpus):
every vlab object of the course folders below whose `specifications` names cpfg or lpfg and that
holds an L-system `.l` file, and every `.lpy` file under L-Py's `share/`, `models/` and `doc/`
(duplicates by content removed). Only the text files the tools read are copied (see KEEP);
ITEMS.tsv lists dialect, item and source path. Usage:

    collect.py VLAB_GIT_DIR LPY_GIT_DIR      # clones of AlgorithmicBotany/vlab and openalea/lpy

at the commits SOURCES.md gives (the script reads HEAD of each)."""
import os
import re
import shutil
import subprocess
import sys

COURSES = ['oofs/ext/11-CPFG', 'oofs/ext/10-manuals/ext/11-CPFG', 'oofs/ext/10-manuals/ext/10-GettingStarted',
           'oofs/ext/10-manuals/ext/20-EnviroPgms', 'oofs/ext/12-LPFG', 'oofs/ext/10-manuals/ext/12-LPFG']
# The files cpfg and lpfg read: L-systems and their headers, view files, colour maps and materials,
# functions, surfaces and contours, environment programs' specifications and data, animation files.
KEEP = re.compile(r'(^specifications$|^LSspecifications$|\.(l|h|v|map|map2|func|fset|mat|s|e|con|spec|a|dat|c|surface|offset|cfg)$)')
TOO_BIG = 64 * 1024  # a terrain patch of 1.2 MB and a compiled library (libcomm.a) are left out
HERE = os.path.dirname(os.path.abspath(__file__))


def git(repo, *args):
    return subprocess.run(['git', '-C', repo, *args], check=True, capture_output=True).stdout


def tree(repo):
    for line in git(repo, 'ls-tree', '-r', '-l', 'HEAD').decode('utf-8', 'replace').splitlines():
        meta, path = line.split('\t', 1)
        _mode, _kind, sha, size = meta.split()
        yield path, sha, size


def vlab_items(repo):
    blobs = {p: (sha, size) for p, sha, size in tree(repo)}
    by_folder = {}
    for p in blobs:
        by_folder.setdefault(os.path.dirname(p), []).append(p)
    names = set()
    for spec in sorted(p for p in blobs if p.endswith('/specifications') and any(p.startswith(c + '/') for c in COURSES)):
        folder = os.path.dirname(spec)
        found = re.search(r'\b(cpfg|lpfg)\b', git(repo, 'show', 'HEAD:' + spec).decode('utf-8', 'replace'))
        files = [p for p in by_folder[folder] if KEEP.search(os.path.basename(p)) and blobs[p][1] != '-' and int(blobs[p][1]) <= TOO_BIG]
        if not found or not any(p.endswith('.l') for p in files):
            continue
        dialect, name = found.group(1), os.path.basename(folder)
        while (dialect, name) in names:
            name += '-2'
        names.add((dialect, name))
        dest = os.path.join(HERE, dialect, name)
        os.makedirs(dest)
        for p in files:
            with open(os.path.join(dest, os.path.basename(p)), 'wb') as f:
                f.write(git(repo, 'cat-file', 'blob', blobs[p][0]))
        yield dialect, f'{dialect}/{name}', folder


def lpy_items(repo):
    seen = set()
    os.makedirs(os.path.join(HERE, 'lpy'))
    for p, sha, _size in sorted(tree(repo)):
        if not p.endswith('.lpy') or p.split('/')[0] not in ('share', 'models', 'doc') or sha in seen:
            continue
        seen.add(sha)
        name = p.replace('/', '--')
        with open(os.path.join(HERE, 'lpy', name), 'wb') as f:
            f.write(git(repo, 'cat-file', 'blob', sha))
        yield 'lpy', f'lpy/{name}', p


def main(vlab, lpy):
    for d in ('cpfg', 'lpfg', 'lpy'):
        shutil.rmtree(os.path.join(HERE, d), ignore_errors=True)
    items = list(vlab_items(vlab)) + list(lpy_items(lpy))
    with open(os.path.join(HERE, 'ITEMS.tsv'), 'w') as f:
        f.writelines('\t'.join(row) + '\n' for row in items)
    for d in ('cpfg', 'lpfg', 'lpy'):
        print(d, sum(1 for row in items if row[0] == d))


if __name__ == '__main__':
    main(sys.argv[1], sys.argv[2])

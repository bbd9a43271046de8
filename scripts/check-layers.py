#!/usr/bin/env python3
"""Checks that every folder of src/ includes only folders below it.

The layers, lowest first (docs/architecture.md). A folder may include its own
files and those of any lower layer; folders on one line are side by side and
must not include each other. Exits 1 and names each offending #include.

    python3 scripts/check-layers.py [SRC_DIR]
"""
import pathlib
import re
import sys

LAYERS = [
    ["geometry"],
    ["world"],
    ["friction"],
    ["detection"],
    ["fluid", "boundary"],
    ["solver"],
    ["measure"],
    ["io"],
    ["drivers"],
    ["analysis"],
    ["sweep"],
    ["app"],
]
GENERATED = {"dilatant"}  # build/generated/dilatant/version.hpp, below everything

level = {folder: k for k, names in enumerate(LAYERS) for folder in names}
src = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "src")
problems = []
for path in sorted(src.rglob("*")):
    if path.suffix not in {".hpp", ".cpp", ".in"} or not path.is_file():
        continue
    folder = path.relative_to(src).parts[0]
    if len(path.relative_to(src).parts) == 1:
        continue  # src/version.hpp.in and the like
    if folder not in level:
        problems.append(f"{path}: folder '{folder}' is not in a layer of scripts/check-layers.py")
        continue
    for n, line in enumerate(path.read_text().splitlines(), 1):
        m = re.match(r'\s*#include "([A-Za-z_]+)/', line)
        if not m or m.group(1) == folder or m.group(1) in GENERATED:
            continue
        target = m.group(1)
        if target not in level:
            problems.append(f"{path}:{n}: includes unknown folder '{target}'")
        elif level[target] >= level[folder]:
            problems.append(f"{path}:{n}: {folder}/ may not include {target}/ (same or higher layer)")
for p in problems:
    print(p)
sys.exit(1 if problems else 0)

#!/usr/bin/env python3
"""Checks that every folder of src/ includes only folders below it.

The layers, lowest first (docs/architecture.md). A folder may include its own
files and those of any lower layer; folders on one line are side by side and
must not include each other. Every #include of every file under src/ is
classified, in either spelling ("solver/x.hpp" or <solver/x.hpp>, with or
without spaces after the #): a file of ours, a generated header, the standard
library, or a library the README lists. One it cannot classify (a relative
"../" path, a macro, an unknown library, a file kind it does not know) is an
error too, so that nothing passes by being unread. Exits 1 and names each
offending line.

    python3 scripts/check-layers.py [SRC_DIR]
    python3 scripts/check-layers.py --self-test   (every rule on a made-up tree)
"""
import pathlib
import re
import sys
import tempfile

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
# The libraries of the README's dependency table, by the folder of their headers.
LIBRARY_FOLDERS = {"Eigen", "fmt", "nlohmann", "toml++", "CLI", "gtest", "gmock", "benchmark",
                   "pybind11", "sys"}
# Headers outside the C++ standard library without a folder: POSIX, OpenMP, MPI, zlib.
LIBRARY_HEADERS = {"unistd.h", "fcntl.h", "spawn.h", "signal.h", "poll.h", "omp.h", "mpi.h",
                   "zlib.h"}
SOURCE_SUFFIXES = {".hpp", ".cpp", ".h", ".inl", ".in"}

INCLUDE = re.compile(r"\s*#\s*include\b\s*(.*)")
level = {folder: k for k, names in enumerate(LAYERS) for folder in names}


def classify(path, folder, spec):
    """None if the include is allowed, else what is wrong with it."""
    m = re.fullmatch(r'(<([^>]+)>|"([^"]+)")\s*(//.*|/\*.*)?', spec)
    if not m:
        return f"cannot read '#include {spec}' (a macro?): spell the header"
    name = m.group(2) or m.group(3)
    parts = name.split("/")
    if ".." in parts or name.startswith(("/", "./")):
        return f"includes '{name}' by a relative or absolute path: name it from src/"
    head = parts[0]
    if len(parts) > 1 and head in level:
        if head != folder and level[head] >= level[folder]:
            return f"{folder}/ may not include {head}/ (same or higher layer)"
        return None
    if len(parts) > 1 and head in GENERATED:
        return None
    if m.group(3):  # "name": a file beside this one, else nothing we know
        if len(parts) == 1 and (path.parent / name).is_file():
            return None
        return f"includes unknown file or folder '{name}'"
    if len(parts) == 1 and ("." not in name or name in LIBRARY_HEADERS):
        return None  # <vector>, <cmath>, <omp.h>
    if len(parts) > 1 and head in LIBRARY_FOLDERS:
        return None
    return f"includes '<{name}>', which is neither ours nor a listed library (scripts/check-layers.py)"


def check(src):
    problems = []
    for path in sorted(p for p in src.rglob("*") if p.is_file()):
        relative = path.relative_to(src).parts
        if len(relative) == 1:
            continue  # src/version.hpp.in and the like
        if path.suffix not in SOURCE_SUFFIXES:
            problems.append(f"{path}: a file of unknown kind in src/ (scripts/check-layers.py)")
            continue
        folder = relative[0]
        if folder not in level:
            problems.append(f"{path}: folder '{folder}' is not in a layer of scripts/check-layers.py")
            continue
        for n, line in enumerate(path.read_text().splitlines(), 1):
            m = INCLUDE.match(line)
            if m:
                problem = classify(path, folder, m.group(1).strip())
                if problem:
                    problems.append(f"{path}:{n}: {problem}")
    return problems


# --self-test: each allowed spelling passes, each forbidden one is named.
ALLOWED = ['#include "geometry/vec3.hpp"', '# include <geometry/vec3.hpp>', '#include "beside.hpp"',
           '#include "dilatant/version.hpp"', '#include <vector>', '#include <omp.h>',
           '#include <Eigen/Core>  // why', '#include "solver/beside.hpp"']
FORBIDDEN = ['#include "app/main.hpp"', '#  include <sweep/plan.hpp>', '#include "../io/config.hpp"',
             '#include MACRO_HEADER', '#include <unknown/lib.hpp>', '#include "missing.hpp"',
             '#include "boundary/wall.hpp"']


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        src = pathlib.Path(tmp) / "src"
        (src / "solver").mkdir(parents=True)
        (src / "fluid").mkdir()
        (src / "solver" / "beside.hpp").write_text("")
        (src / "solver" / "a.inl").write_text("\n".join(ALLOWED) + "\n")
        (src / "fluid" / "b.h").write_text("\n".join(FORBIDDEN) + "\n")
        (src / "fluid" / "notes.txt").write_text("")
        reports = check(src)
    lines = {int(p.split(":")[1]) for p in reports if "/b.h:" in p}
    others = [p for p in reports if "/b.h:" not in p]
    expected = set(range(1, len(FORBIDDEN) + 1))
    if lines != expected or len(others) != 1 or "notes.txt" not in others[0]:
        print(f"check-layers self-test: reported lines {sorted(lines)} of {sorted(expected)}, "
              f"other reports {others}")
        return 1
    print(f"check-layers self-test: {len(ALLOWED)} allowed includes passed, "
          f"{len(FORBIDDEN)} forbidden ones and a stray file reported")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    problems = check(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "src"))
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

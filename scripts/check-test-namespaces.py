#!/usr/bin/env python3
"""Checks that each test file keeps its code in a namespace named after it.

scripts/build.sh compiles the tests in unity batches (16 files in one
translation unit), and which files share a batch changes whenever a file is
added. Two files' helpers of the same name (a kEps, a parse() of their own)
would then meet in one batch and break the build of a change that touched
neither. So every namespace a file opens at its top level is
dilatant[::<folder namespace>]::<file stem>, e.g. dilatant::incline_test in
tests/validation/incline_test.cpp; anonymous namespaces and aliases
(namespace fs = ...) inside it are the file's own business. Helper headers
must not name a namespace `testing` (it would hide GoogleTest's ::testing in
every file of the batch after them). Exits 1 and names each offending line.

    python3 scripts/check-test-namespaces.py [TESTS_DIR]
"""
import pathlib
import re
import sys

OPENING = re.compile(r"^namespace\s+([\w:]+)\s*\{")  # top level: column 0


def problems(tests: pathlib.Path) -> list[str]:
    found = []
    for path in sorted(tests.rglob("*_test.cpp")):
        stem = path.stem
        opened = False
        for number, line in enumerate(path.read_text().splitlines(), 1):
            m = OPENING.match(line)
            if not m:
                continue
            opened = True
            parts = m.group(1).split("::")
            if parts[0] != "dilatant" or parts[-1] != stem or len(parts) > 3:
                found.append(f"{path}:{number}: namespace {m.group(1)}: the file's code belongs "
                             f"in dilatant[::folder]::{stem} (unity batches, tests/CMakeLists.txt)")
        if not opened:
            found.append(f"{path}: no namespace dilatant::{stem}: the file's code belongs in one")
    for path in sorted(tests.rglob("*.hpp")):
        for number, line in enumerate(path.read_text().splitlines(), 1):
            if re.match(r"^namespace\s+([\w:]+::)?testing\b", line):
                found.append(f"{path}:{number}: a namespace named testing hides GoogleTest's "
                             "::testing in the files after it")
    return found


def main() -> int:
    tests = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "tests")
    found = problems(tests)
    for p in found:
        print(p, file=sys.stderr)
    if not found:
        print(f"check-test-namespaces: every test file under {tests} keeps its own namespace")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())

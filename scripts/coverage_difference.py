#!/usr/bin/env python3
"""Lines of the project's sources that one test run executed and another did not.

    coverage_difference.py --source src KEPT.lcov LEFT.lcov LIST

KEPT.lcov and LEFT.lcov are line counts (llvm-cov export -format=lcov) of the
tests a sanitizer stage keeps and of those it leaves out (LIST names them).
Prints each line under --source that LEFT ran and KEPT did not, with its text,
and exits 1 if there is any; exits 0 with a one-line summary otherwise
(scripts/coverage-proof.sh; docs/testing.md, "Fourth round").
"""
import argparse
import sys
from pathlib import Path


def executed_lines(lcov: Path, source: Path) -> dict[Path, set[int]]:
    """The lines with a non-zero count, per file under `source`."""
    lines: dict[Path, set[int]] = {}
    current = None
    for record in lcov.read_text().splitlines():
        if record.startswith("SF:"):
            path = Path(record[3:]).resolve()
            current = path if path.is_relative_to(source) else None
        elif record.startswith("DA:") and current is not None:
            number, count = record[3:].split(",")[:2]
            if int(count) > 0:
                lines.setdefault(current, set()).add(int(number))
    return lines


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("kept", type=Path)
    parser.add_argument("left", type=Path)
    parser.add_argument("list", type=Path)
    args = parser.parse_args()
    source = args.source.resolve()
    kept = executed_lines(args.kept, source)
    left = executed_lines(args.left, source)
    if not kept:
        print(f"{args.kept}: no line under {args.source} was run", file=sys.stderr)
        return 1
    only_left = {f: sorted(n - kept.get(f, set())) for f, n in left.items()}
    only_left = {f: n for f, n in only_left.items() if n}
    total_kept = sum(len(n) for n in kept.values())
    total_left = sum(len(n) for n in left.values())
    if not only_left:
        print(f"{args.list}: its tests run {total_left} lines of {args.source}/; "
              f"the tests the stage keeps run all of them (and {total_kept} in all)")
        return 0
    count = sum(len(n) for n in only_left.values())
    print(f"{args.list}: its tests run {count} lines of {args.source}/ "
          "that no test the stage keeps runs:")
    for path, numbers in sorted(only_left.items()):
        text = path.read_text().splitlines()
        for number in numbers:
            print(f"  {path.relative_to(source.parent)}:{number}: {text[number - 1].strip()}")
    return 1


if __name__ == "__main__":
    sys.exit(main())

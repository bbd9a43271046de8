#!/usr/bin/env python3
"""The stage table and the slowest tests of one scripts/test.sh run.

    test_report.py STAGES_TSV [LABEL=LOG ...]

STAGES_TSV holds one line per stage: name, wall seconds, ok|FAILED.
Each LOG is a ctest log (lines "  3/400 Test  #12: name ....   Passed   9.87 sec",
ctest's own timing) or a GoogleTest log ("[       OK ] Suite.Test (1234 ms)");
LABEL names the stage it came from. Prints Markdown (docs/testing.md keeps
the tables of reference runs); scripts/test.sh writes it to build/test-report.md.
"""
import re
import sys

CTEST_LINE = re.compile(r"^\s*\d+/\d+ Test\s+#\d+: (.+?) \.+\**\s*(\w[\w ]*?)\s+([0-9.]+) sec")
GTEST_LINE = re.compile(r"^\[\s+(OK|FAILED)\s+\] (\S+) \((\d+) ms\)")
SLOWEST = 15


def read_stages(path):
    stages = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            name, seconds, status = line.rstrip("\n").split("\t")
            stages.append((name, int(seconds), status))
    return stages


def read_tests(label, path):
    """(seconds, name, stage, outcome) of every test the log timed."""
    tests = []
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                if m := CTEST_LINE.match(line):
                    tests.append((float(m[3]), m[1], label, m[2].strip()))
                elif m := GTEST_LINE.match(line):
                    tests.append((int(m[3]) / 1000.0, m[2], label, "Passed" if m[1] == "OK" else "Failed"))
    except FileNotFoundError:
        pass  # a stage that never reached its tests
    return tests


def minutes(seconds):
    return f"{seconds // 60}:{seconds % 60:02d}"


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    stages = read_stages(argv[1])
    tests = []
    for arg in argv[2:]:
        label, _, path = arg.partition("=")
        tests += read_tests(label, path)

    total = sum(s for _, s, _ in stages)
    print("| stage | wall time (min:s) | status |")
    print("|---|---:|---|")
    for name, seconds, status in stages:
        print(f"| {name} | {minutes(seconds)} | {status} |")
    print(f"| **total** | **{minutes(total)}** | |")
    print()
    print(f"{len(tests)} tests timed; the {min(SLOWEST, len(tests))} slowest:")
    print()
    print("| test | stage | seconds | outcome |")
    print("|---|---|---:|---|")
    for seconds, name, label, outcome in sorted(tests, reverse=True)[:SLOWEST]:
        print(f"| {name} | {label} | {seconds:.1f} | {outcome} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

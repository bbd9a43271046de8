#!/usr/bin/env python3
"""Compares two result folders of dilatant file by file (scripts/compare-outputs.sh).

    python3 scripts/compare_outputs.py OLD_DIR NEW_DIR [--strict-config]

Every file must be byte-identical, except
  * summary.json: compared key by key, every value exactly, but the keys that
    measure the run's cost (wall time, time by stage, ns per contact update,
    memory) and the version;
  * config.toml and a sweep's sweep.toml (resolved configurations): their
    differing lines are shown, and count only with --strict-config (a refactor
    may change how the resolved configuration is presented);
  * plots (*.png, *.pdf, *.svg): not compared (matplotlib output);
  * .dilatant.lock (the folder's lock, empty once released; since 0.13.1):
    not compared, so a folder of an older version compares with a newer's;
  * the two folders' own paths, where a file names them, are taken as equal.
A file that differs only in numbers, each by at most 1e-14 relative (the last
bits of a double), is reported as "round-off", with its largest relative
difference; it counts as a difference unless --accept-roundoff is given.
Prints one line per difference. Exit status: 0 identical (or round-off only
with --accept-roundoff), 3 round-off only, 1 anything else differs, 2 usage.
"""
import re
import difflib
import json
import pathlib
import sys

LOCK_FILE = ".dilatant.lock"  # src/io/folder_lock.hpp: no result, so not compared
COST_KEYS = {
    "wall_time_s", "time_build_s", "time_detection_s", "time_solve_s", "time_measure_s",
    "time_other_s", "ns_per_contact_update", "wall_time_per_strain_s", "peak_memory_mib",
    "version",
}
SKIPPED_SUFFIXES = {".png", ".pdf", ".svg"}
RESOLVED_CONFIGS = {"config.toml", "sweep.toml"}


def first_difference(a: bytes, b: bytes) -> str:
    la, lb = a.decode(errors="replace").splitlines(), b.decode(errors="replace").splitlines()
    for n, (x, y) in enumerate(zip(la, lb), 1):
        if x != y:
            return f"line {n}: old {x[:100]!r} new {y[:100]!r}"
    return f"old has {len(la)} lines, new {len(lb)}"


NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
ROUND_OFF = 1e-14


def round_off_only(a: str, b: str):
    """The largest relative difference if a and b differ only in numbers, each by
    at most ROUND_OFF relative; else None."""
    if NUMBER.sub("#", a) != NUMBER.sub("#", b):
        return None
    largest = 0.0
    for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
        if x == y:
            continue
        fx, fy = float(x), float(y)
        scale = max(abs(fx), abs(fy))
        rel = abs(fx - fy) / scale if scale > 0 else 0.0
        if rel > ROUND_OFF:
            return None
        largest = max(largest, rel)
    return largest


def compare_summary(a: pathlib.Path, b: pathlib.Path) -> list:
    old, new = json.loads(a.read_text()), json.loads(b.read_text())
    out = []
    for key in sorted(set(old) | set(new)):
        if key in COST_KEYS:
            continue
        if key not in old or key not in new:
            out.append(f"key {key} only in {'old' if key in old else 'new'}")
        elif old[key] != new[key]:
            out.append(f"{key}: old {old[key]!r} new {new[key]!r}")
    return out


def compare_csv_without_cost(a: pathlib.Path, b: pathlib.Path) -> list:
    """flowcurves.csv carries each point's wall time: drop the cost columns."""
    def rows(p):
        lines = p.read_text().splitlines()
        header = lines[0].split(",") if lines else []
        keep = [k for k, name in enumerate(header) if name not in COST_KEYS]
        return [",".join(line.split(",")[k] for k in keep if k < len(line.split(",")))
                for line in lines]
    ra, rb = rows(a), rows(b)
    if ra == rb:
        return []
    return [first_difference("\n".join(ra).encode(), "\n".join(rb).encode())]


def main() -> int:
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    strict_config = "--strict-config" in sys.argv[1:]
    accept_roundoff = "--accept-roundoff" in sys.argv[1:]
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    old_dir, new_dir = map(pathlib.Path, args)
    names = sorted({p.relative_to(old_dir) for p in old_dir.rglob("*") if p.is_file()} |
                   {p.relative_to(new_dir) for p in new_dir.rglob("*") if p.is_file()})
    counted, compared, rounded = 0, 0, 0
    for name in names:
        a, b = old_dir / name, new_dir / name
        if name.suffix in SKIPPED_SUFFIXES or name.name == LOCK_FILE:
            continue
        compared += 1
        if not a.exists() or not b.exists():
            print(f"  {name}: only in {'old' if a.exists() else 'new'}")
            counted += 1
            continue
        if name.name in RESOLVED_CONFIGS:
            old_lines = a.read_text().replace(str(old_dir), "<DIR>").splitlines()
            new_lines = b.read_text().replace(str(new_dir), "<DIR>").splitlines()
            changed = [line for line in difflib.unified_diff(old_lines, new_lines, lineterm="", n=0)
                       if line[:1] in "+-" and line[:3] not in ("+++", "---")]
            for line in changed[:12]:
                print(f"  {name}: {line}{'' if strict_config else '  (shown, not counted)'}")
            if changed and strict_config:
                counted += 1
            continue
        if name.name == "summary.json":
            diffs = compare_summary(a, b)
        elif name.name == "flowcurves.csv":
            diffs = compare_csv_without_cost(a, b)
        elif a.read_bytes() == b.read_bytes():
            continue
        else:
            # Only files that differ have the folders' paths taken as equal: in a
            # binary file (checkpoint.bin) a short folder name (v1) can be any
            # bytes, and equal files must compare equal whatever their folders.
            ta = a.read_bytes().replace(str(old_dir).encode(), b"<DIR>")
            tb = b.read_bytes().replace(str(new_dir).encode(), b"<DIR>")
            diffs = [] if ta == tb else [first_difference(ta, tb)]
            if diffs:
                rel = round_off_only(ta.decode(errors="replace"), tb.decode(errors="replace"))
                if rel is not None:
                    print(f"  {name}: round-off only, largest relative difference {rel:.1e}"
                          f"; first: {diffs[0]}")
                    rounded += 1
                    continue
        if not diffs:
            continue
        for d in diffs[:5]:
            print(f"  {name}: {d}")
        counted += 1
    print(f"  {compared} files compared, {counted} differ"
          f"{f', {rounded} in round-off only' if rounded else ''}")
    if counted:
        return 1
    return 3 if rounded and not accept_roundoff else 0


if __name__ == "__main__":
    sys.exit(main())

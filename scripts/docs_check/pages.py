"""A docs page's markers, checked one by one."""
from . import Problem
from .markers import MARKER, SEPARATOR, TABLE_ROW, parse_marker
from .tables import check_table
from .values import check_value


def check_file(md, root, cache, problems, listing=None):
    text = (root / md).read_text()
    lines = text.split("\n")
    offsets, pos = [], 0
    for line in lines:
        offsets.append(pos)
        pos += len(line) + 1
    guarded = 0
    for m in MARKER.finditer(text):
        start = text.count("\n", 0, m.start()) + 1
        end = text.count("\n", 0, m.end()) + 1
        kind = m.group(1)
        try:
            marker = parse_marker(kind, m.group(2))
            i = end  # 0-based index of the line after the marker's last line
            while i < len(lines) and lines[i].strip() == "":
                i += 1
            if kind == "table-source":
                if not (i + 1 < len(lines) and TABLE_ROW.match(lines[i]) and SEPARATOR.match(lines[i + 1])):
                    raise Problem("no table follows the table-source marker")
                j = i
                while j < len(lines) and TABLE_ROW.match(lines[j]):
                    j += 1
                table = [(k + 1, lines[k]) for k in range(i, j)]
                check_table(md, start, marker, table, root, cache, problems)
                if listing is not None:
                    listing.append(f"{md}:{i + 1}: table of {j - i - 2} rows from {marker['file']}")
            else:
                j = i
                while j < len(lines) and lines[j].strip() != "":
                    j += 1
                check_value(md, start, marker, "\n".join(lines[i:j]), root, cache, problems)
                if listing is not None:
                    listing.append(f"{md}:{start}: '{marker['says']}' from {marker['file']}")
            guarded += 1
        except Problem as e:
            problems.append(f"{md}:{start}: {e}")
    return guarded


def run(root, dirs, listing=None):
    problems, cache, guarded = [], {}, 0
    for d in dirs:
        for md in sorted((root / d).glob("*.md")):
            guarded += check_file(md.relative_to(root).as_posix(), root, cache, problems, listing)
    return problems, guarded

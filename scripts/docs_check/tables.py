"""A docs table against the file its marker names."""
from . import Problem
from .markers import plain, says_no_value, split_row
from .numerals import agrees, parse_numbers, show, to_float
from .sources import read_rows, select


def check_cell(cell, refs, row_for, report, column_name):
    """Compares one docs cell with the file's values its refs name."""
    values = []
    for ref in refs:
        if ref["skip"]:
            values.append(None)
            continue
        row = row_for(ref)
        values.append(row.get(ref["name"], ""))
    checked = [(r, v) for r, v in zip(refs, values) if not r["skip"]]
    if says_no_value(cell):  # an optional value may be left out of the cell
        present = [v for r, v in checked if (v or "").strip() != "" and not r["optional"]]
        if present:
            report(column_name, cell, " ".join(present))
        return
    numbers = parse_numbers(plain(cell))
    if len(checked) == 1 and not numbers and to_float(checked[0][1]) is None:
        if plain(cell) != (checked[0][1] or "").strip():
            report(column_name, plain(cell), checked[0][1] or "(empty)")
        return
    required = sum(1 for r in refs if not r["optional"])
    if not (required <= len(numbers) <= len(refs)):
        report(column_name, plain(cell),
               f"{len(refs)} value(s) ({', '.join(r.get('name', '_') for r in refs)})"
               f" where the cell shows {len(numbers)} number(s)")
        return
    for (docs_value, half), ref, value in zip(numbers, refs, values):
        if ref["skip"]:
            continue
        f = to_float(value)
        if f is None:
            report(column_name, show_docs(docs_value, half), value or "(empty)")
            continue
        if ref["factor"] is not None:
            f *= ref["factor"]
        if not agrees(docs_value, half, f):
            report(column_name, show_docs(docs_value, half), show(f))


def show_docs(value, half):
    return show(value)


def check_table(md, marker_line, marker, table_lines, root, cache, problems):
    rows, columns = read_rows(root, marker["file"], cache)
    specs = marker["columns"]
    for spec in specs:
        for ref in spec or []:
            if not ref["skip"]:
                if ref["name"] not in columns:
                    raise Problem(f"{marker['file']} has no column '{ref['name']}'")
                for c, _, _ in ref["cond"]:
                    if c not in columns:
                        raise Problem(f"{marker['file']} has no column '{c}'")
    for c, _, _ in marker["where"]:
        if c not in columns:
            raise Problem(f"{marker['file']} has no column '{c}'")
    pool = select(rows, marker["where"])
    (_, head), body = table_lines[0], table_lines[2:]
    names = split_row(head)
    if len(names) != len(specs):
        raise Problem(f"the table has {len(names)} columns, the marker's columns= {len(specs)}")
    key_index = []
    for k in marker["key"]:
        idx = [i for i, s in enumerate(specs)
               if s and not s[0]["skip"] and s[0]["name"] == k and not s[0]["cond"]]
        if not idx:
            raise Problem(f"key column '{k}' does not begin an entry of columns=")
        key_index.append(idx[0])
    if not marker["key"] and len(body) != len(pool):
        problems.append(f"{md}:{marker_line}: the table has {len(body)} rows, "
                        f"{marker['file']} has {len(pool)} (after where)")
    for n, (line_no, line) in enumerate(body):
        cells = split_row(line)
        if len(cells) != len(specs):
            problems.append(f"{md}:{line_no}: the row has {len(cells)} cells, the table {len(specs)}")
            continue
        key_text = ", ".join(f"{marker['key'][j]} {plain(cells[i])}" for j, i in enumerate(key_index))
        row_label = key_text or f"{n + 1}"

        def candidates(extra):
            cand = select(pool, extra)
            for j, i in enumerate(key_index):
                nums = parse_numbers(plain(cells[i]))[:1]  # a key is the cell's first value
                name = marker["key"][j]
                if len(nums) == 1:
                    # A key is equal to the file's value; if none is, rounded to it.
                    v, h = nums[0]
                    exact = [r for r in cand if to_float(r.get(name)) == v]
                    cand = exact or [r for r in cand if to_float(r.get(name)) is not None
                                     and agrees(v, h, to_float(r.get(name)))]
                else:
                    cand = [r for r in cand if plain(cells[i]) == (r.get(name) or "").strip()]
            return cand

        def row_for(ref, n=n):
            if marker["key"]:
                cand = candidates(ref["cond"])
                if len(cand) != 1:
                    raise Problem(f"{'no' if not cand else len(cand)} rows of {marker['file']} "
                                  f"match row {row_label}"
                                  + (f" with {ref['cond']}" if ref["cond"] else ""))
                return cand[0]
            if ref["cond"]:
                cand = select(pool, ref["cond"])
                if n >= len(cand):
                    raise Problem(f"row {row_label}: {marker['file']} has too few rows with {ref['cond']}")
                return cand[n]
            if n >= len(pool):
                raise Problem(f"row {row_label}: {marker['file']} has too few rows")
            return pool[n]

        def report(column, docs, file_value, line_no=line_no, row_label=row_label):
            problems.append(f"{md}:{line_no}: column {column}, row {row_label}: "
                            f"docs say {docs}, CSV says {file_value}")

        for i, (cell, spec) in enumerate(zip(cells, specs)):
            if spec is None:
                continue
            if i in key_index:  # its first value selected the row; check the rest
                if len(spec) == 1:
                    continue
                spec = [{"skip": True, "optional": False}] + spec[1:]
            try:
                check_cell(cell, spec, row_for, report, names[i])
            except Problem as e:
                problems.append(f"{md}:{line_no}: {e}")
                break

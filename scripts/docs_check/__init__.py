"""The docs check: docs tables and prose numbers against the committed files
they were copied from. The marker syntax and the command line are described in
scripts/check-docs-tables.py, which runs it; the parts, in the order a page is
read:

* numerals.py: numbers as docs write them, and when a rounded one agrees;
* sources.py:  a marker's file as rows, and the conditions that select rows;
* markers.py:  a marker's arguments and a table's cells;
* tables.py:   a table against its file;
* values.py:   a number in prose against its file (one value, or a count,
               minimum or maximum over rows);
* pages.py:    a docs page's markers, one by one;
* self_test.py: made-up pages it must pass and fail.
"""


class Problem(Exception):
    """A marker that cannot be checked: a missing file, column or row."""

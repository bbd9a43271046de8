"""Runs the code cells of a notebook in order, in one namespace, without
Jupyter (not a dependency): what CI checks of examples/python/*.ipynb.

    python3 python/tests/run_notebook.py NOTEBOOK
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")


def main():
    notebook = json.load(open(sys.argv[1]))
    namespace = {"__name__": "__main__"}
    for n, cell in enumerate(notebook["cells"]):
        if cell["cell_type"] == "code":
            exec(compile("".join(cell["source"]), f"{sys.argv[1]}[cell {n}]", "exec"), namespace)
    print(f"{sys.argv[1]}: every code cell ran")


if __name__ == "__main__":
    main()

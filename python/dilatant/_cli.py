"""The `dilatant` command that `pip install` puts on the environment's PATH
(pyproject.toml [project.scripts]): it replaces itself with the C++ executable
installed inside the package (dilatant/_bin/dilatant), telling it to draw plots
with this environment's Python (DILATANT_PYTHON, src/app/python_script.hpp);
the executable finds the plot scripts in dilatant/plots/ beside it."""
import os
import sys
from pathlib import Path

EXECUTABLE = Path(__file__).resolve().parent / "_bin" / "dilatant"


def main():
    if not EXECUTABLE.is_file():
        sys.exit(f"dilatant: error: {EXECUTABLE} is missing: this package was not "
                 "installed by `pip install` (from a build folder run <build>/dilatant)")
    env = dict(os.environ)
    env.setdefault("DILATANT_PYTHON", sys.executable)
    os.execve(EXECUTABLE, [str(EXECUTABLE), *sys.argv[1:]], env)


if __name__ == "__main__":
    main()

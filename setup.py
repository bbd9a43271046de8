"""Builds dilatant for `pip install .` (pyproject.toml): CMake configures this
source tree into a temporary folder and builds two targets, the Python module
dilatant._core and the `dilatant` executable; both are copied into the
package (dilatant/_core*.so, dilatant/_bin/dilatant). Everything is built in
build-pip/ of the source tree (kept: a second install rebuilds what changed). The `dilatant` command on
the environment's PATH is python/dilatant/_cli.py, which runs that executable
with this environment's Python for the plots.

Environment:
  DILATANT_CMAKE_ARGS   extra CMake arguments (e.g. -DDILATANT_WITH_MPI=OFF)
  CMAKE_BUILD_PARALLEL_LEVEL   compile jobs (default: all cores)
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    """The version CMakeLists.txt declares (one source of truth)."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(dilatant VERSION ([0-9.]+)", text)
    if not match:
        sys.exit("setup.py: no 'project(dilatant VERSION x.y.z' in CMakeLists.txt")
    return match.group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            sys.exit("setup.py: cmake not found: install the build dependencies first "
                     "(bash scripts/install-deps.sh, README.md)")
        module_path = Path(self.get_ext_fullpath(ext.name)).resolve()
        package_dir = module_path.parent
        tree = Path(self.build_temp).resolve() / "cmake"
        tree.mkdir(parents=True, exist_ok=True)
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        configure = ["cmake", "-S", str(ROOT), "-B", str(tree), *generator,
                     "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                     "-DDILATANT_BUILD_BENCHMARKS=OFF", "-DDILATANT_BUILD_PYTHON=ON",
                     "-DDILATANT_WERROR=OFF", "-DCMAKE_UNITY_BUILD=ON",
                     "-DCMAKE_UNITY_BUILD_BATCH_SIZE=16",
                     f"-DPython_EXECUTABLE={sys.executable}",
                     *shlex.split(os.environ.get("DILATANT_CMAKE_ARGS", ""))]
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(tree), "--parallel", jobs,
                        "--target", "dilatant_python", "dilatant"], check=True)
        built = sorted((tree / "python" / "dilatant").glob("_core*.so"))
        if not built:
            sys.exit(f"setup.py: CMake built no _core*.so in {tree / 'python' / 'dilatant'}")
        package_dir.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[-1], module_path)
        bin_dir = package_dir / "_bin"
        bin_dir.mkdir(exist_ok=True)
        shutil.copy2(tree / "dilatant", bin_dir / "dilatant")
        os.chmod(bin_dir / "dilatant", 0o755)


setup(
    version=project_version(),
    package_dir={"": "python"},
    packages=["dilatant", "dilatant.plots"],
    package_data={"dilatant": ["py.typed", "*.pyi"]},
    ext_modules=[CMakeExtension("dilatant._core")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    # Not build/: that is scripts/build.sh's CMake tree.
    options={"build": {"build_base": "build-pip"}},
)

"""Build the Python package gmcc with CMake (pyproject.toml; docs/python.md "Installing").

setuptools calls build_ext, which configures the CMake project with the Python that runs pip
(Release, Ninja, only what the module needs: no command line, tests or benchmarks), builds the
target gmcc_python_core and puts the extension gmcc/_core*.so where setuptools packs it. The
pure-Python files come from python/gmcc/, and the shipped spectral data and samples from data/
into gmcc/data (gmcc.data_dir() finds them there).

Environment:
  GMCC_CMAKE_BUILD_DIR  a CMake build folder to use (default build/pip/cmake). If it is already
                        configured, it is only built, with its own options (the tests reuse the
                        test build so that the module is not compiled twice).
  CMAKE_BUILD_PARALLEL_LEVEL  jobs for the build (CMake's own variable).
"""

import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

ROOT = os.path.dirname(os.path.abspath(__file__))


def version():
    """The version of CMakeLists.txt's project(), the one every gmcc output records."""
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        match = re.search(r"project\(gmcc\s+VERSION\s+([0-9.]+)", f.read())
    if not match:
        raise RuntimeError("CMakeLists.txt: no project(gmcc VERSION …)")
    return match.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.environ.get("GMCC_CMAKE_BUILD_DIR") or os.path.join(ROOT, "build", "pip", "cmake")
        build_dir = os.path.abspath(build_dir)
        if not os.path.isfile(os.path.join(build_dir, "CMakeCache.txt")):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.check_call(["cmake", "-S", ROOT, "-B", build_dir, *generator,
                                   "-DCMAKE_BUILD_TYPE=Release",
                                   f"-DPython_EXECUTABLE={sys.executable}",
                                   "-DGMCC_BUILD_PYTHON=ON", "-DGMCC_BUILD_CLI=OFF",
                                   "-DGMCC_BUILD_TESTS=OFF", "-DGMCC_BUILD_BENCHMARKS=OFF"])
        subprocess.check_call(["cmake", "--build", build_dir, "--target", "gmcc_python_core"])
        package = os.path.join(build_dir, "python", "gmcc")
        built = [f for f in os.listdir(package) if f.startswith("_core") and f.endswith(".so")]
        if len(built) != 1:
            raise RuntimeError(f"{package}: expected one _core*.so after the build, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)


class BuildPy(build_py):
    """The package's Python files, then data/'s CSV, Markdown and text files into gmcc/data (as
    cmake --install puts them)."""

    def run(self):
        super().run()
        source = os.path.join(ROOT, "data")
        target = os.path.join(self.build_lib, "gmcc", "data")
        for folder, _, files in os.walk(source):
            for f in sorted(files):
                if f.endswith((".csv", ".md", ".txt")):
                    out = os.path.join(target, os.path.relpath(folder, source), f)
                    os.makedirs(os.path.dirname(out), exist_ok=True)
                    shutil.copyfile(os.path.join(folder, f), out)


os.makedirs(os.path.join(ROOT, "build", "pip"), exist_ok=True)  # egg_base below
setup(
    version=version(),
    packages=["gmcc"],
    package_dir={"gmcc": "python/gmcc"},
    package_data={"gmcc": ["__init__.pyi", "py.typed"]},
    ext_modules=[Extension("gmcc._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildPy},
    options={"build": {"build_base": os.path.join("build", "pip", "setuptools")},
             "egg_info": {"egg_base": os.path.join("build", "pip")}},
    zip_safe=False,
)

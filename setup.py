"""setup.py -- builds the Python package symrep with CMake (pyproject.toml; docs/python.md).

    /usr/bin/python3 -m pip install --no-build-isolation .

build_ext configures the sources with CMake (Release, -DSYMREP_BUILD_TESTS=OFF
-DSYMREP_BUILD_BENCH=OFF, this interpreter as PYTHON_EXECUTABLE) in setuptools' build folder
(build-pip/ at the top of the sources), builds only the target _symrep and puts the module into
the package. build_py adds the engine's rule files (rules/*.rules -> symrep/rules, found through
symrep/_rules.py); data_files installs the kernel spec as PREFIX/share/jupyter/kernels/symrep.

Environment:
  SYMREP_CMAKE_BUILD_DIR  an existing CMake build tree of these sources (configured with
                          -DSYMREP_BUILD_PYTHON=ON for this interpreter): its module
                          BUILD/python/symrep/_symrep*.so is taken as it is, nothing is compiled
                          (build it first: cmake --build BUILD --target _symrep). setuptools'
                          own files then go to BUILD/pip. tests/install/test_pip.sh uses this.
  SYMREP_CMAKE_ARGS       more arguments for the configure step (e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  CMAKE_BUILD_PARALLEL_LEVEL  the number of compile jobs (default: the number of processors)
  CMAKE                   the cmake program (default: cmake)
"""

import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))


def cmake_version():
    """The one version number: project(symrep VERSION x.y.z) of CMakeLists.txt."""
    with open(os.path.join(HERE, "CMakeLists.txt")) as f:
        m = re.search(r"project\(\s*symrep\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+)", f.read())
    if not m:
        sys.exit("setup.py: no project(symrep VERSION x.y.z) in CMakeLists.txt")
    return m.group(1)


def reused_build_dir():
    d = os.environ.get("SYMREP_CMAKE_BUILD_DIR")
    return os.path.abspath(d) if d else None


class cmake_build_ext(build_ext):
    """The extension symrep._symrep, built by CMake (the target _symrep of repl/python)."""

    def build_extension(self, ext):
        build_dir = reused_build_dir()
        if build_dir is None:
            build_dir = os.path.abspath(os.path.join(self.build_temp, "cmake"))
            self.cmake(build_dir)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = os.path.join(build_dir, "python", "symrep", "_symrep" + suffix)
        if not os.path.isfile(built):
            found = glob.glob(os.path.join(build_dir, "python", "symrep", "_symrep*.so"))
            sys.exit("setup.py: no %s in %s%s" % (
                os.path.basename(built), build_dir,
                " (it holds %s: built for another interpreter than %s)" % (", ".join(map(os.path.basename, found)), sys.executable)
                if found else " (build the target _symrep there first, with -DSYMREP_BUILD_PYTHON=ON and pybind11)"))
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)
        shutil.copymode(built, target)

    def cmake(self, build_dir):
        cmake = os.environ.get("CMAKE", "cmake")
        if shutil.which(cmake) is None:
            sys.exit("setup.py: cmake is needed to build the module (Debian: cmake)")
        configure = [cmake, "-S", HERE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                     "-DSYMREP_BUILD_TESTS=OFF", "-DSYMREP_BUILD_BENCH=OFF", "-DSYMREP_BUILD_PYTHON=ON",
                     "-DPYTHON_EXECUTABLE=" + sys.executable]
        configure += shlex.split(os.environ.get("SYMREP_CMAKE_ARGS", ""))
        subprocess.check_call(configure)
        cache = open(os.path.join(build_dir, "CMakeCache.txt")).read()
        if re.search(r"^pybind11_DIR:PATH=.*NOTFOUND", cache, re.M):
            sys.exit("setup.py: CMake did not find pybind11 (Debian: pybind11-dev), so there is no module to build")
        build = [cmake, "--build", build_dir, "--target", "_symrep"]
        if not os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL"):
            build += ["--parallel", str(os.cpu_count() or 1)]
        subprocess.check_call(build)


class build_py_with_rules(build_py):
    """The package and the engine's rule files (rules/*.rules -> symrep/rules)."""

    def run(self):
        super().run()
        rules = os.path.join(self.build_lib, "symrep", "rules")
        os.makedirs(rules, exist_ok=True)
        for f in sorted(glob.glob(os.path.join(HERE, "rules", "*.rules"))):
            self.copy_file(f, os.path.join(rules, os.path.basename(f)))


# setuptools' build folders: not build/ (the usual CMake build tree of the sources)
build_base = os.path.join(reused_build_dir(), "pip") if reused_build_dir() else os.path.join(HERE, "build-pip")
os.makedirs(build_base, exist_ok=True)
kernelspec = sorted(f for f in glob.glob("repl/python/symrep/kernelspec/*") if os.path.isfile(f))

setup(
    version=cmake_version(),
    ext_modules=[Extension("symrep._symrep", sources=[])],
    cmdclass={"build_ext": cmake_build_ext, "build_py": build_py_with_rules},
    data_files=[("share/jupyter/kernels/symrep", kernelspec)],
    options={"build": {"build_base": build_base}, "egg_info": {"egg_base": build_base}},
)

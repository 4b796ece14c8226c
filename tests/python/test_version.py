"""One version number (docs/library.md "Versions"): project(symrep VERSION x.y.z) in CMakeLists.txt
is symrep.__version__, symrep.version and what `symrep --version` prints."""
import os
import re
import subprocess

import symrep
from conftest import SOURCE_DIR


def cmake_version():
    with open(os.path.join(SOURCE_DIR, "CMakeLists.txt")) as f:
        m = re.search(r"project\(\s*symrep\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+)", f.read())
    assert m, "no project(symrep VERSION x.y.z) in CMakeLists.txt"
    return m.group(1)


def test_version_is_the_one_of_cmakelists():
    assert symrep.__version__ == cmake_version()
    assert symrep.version == symrep.__version__
    assert "__version__" in dir(symrep)


def test_the_program_says_the_same():
    binary = os.path.join(os.environ.get("SYMREP_BINARY_DIR", os.path.join(SOURCE_DIR, "build")), "symrep")
    if not os.path.exists(binary):
        import pytest

        pytest.skip("no symrep program at " + binary)
    out = subprocess.run([binary, "--version"], capture_output=True, text=True, check=True).stdout
    assert out == "symrep %s\n" % symrep.__version__

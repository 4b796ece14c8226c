#!/usr/bin/env bash
# tests/install/test_pip.sh BUILD_DIR SOURCE_DIR -- `pip install .` of the sources, as a Python user
# meets it (ctest: install.pip; docs/python.md "Installing").
#
# pip-installs the source tree (pyproject.toml, setup.py) into a temporary prefix -- not the
# system's site-packages -- offline (--no-index, --no-build-isolation: Debian's setuptools), with
# --no-deps (numpy comes from Debian). Instead of compiling the module again, setup.py takes the
# one this build made (SYMREP_CMAKE_BUILD_DIR; the normal `pip install .` runs CMake itself, see
# setup.py). Then check_python_package.py imports symrep from a clean interpreter whose path holds
# only that prefix, evaluates a statement, checks __version__, the package's files and the kernel
# spec (PREFIX/share/jupyter/kernels/symrep, no path of this tree), and the Pygments entry point.
# $PYTHON: the interpreter the module was built for (default /usr/bin/python3).
set -euo pipefail

if [[ $# -ne 2 ]]; then
    echo "usage: $0 BUILD_DIR SOURCE_DIR" >&2
    exit 2
fi
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
python=${PYTHON:-/usr/bin/python3}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/symrep-pip-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() {
    echo "test_pip: FAILED: $*" >&2
    exit 1
}

suffix=$("$python" -c 'import sysconfig; print(sysconfig.get_config_var("EXT_SUFFIX"))')
module=$build/python/symrep/_symrep$suffix
[[ -f $module ]] || fail "no $module: build the target _symrep first"
# a build folder of our own that holds this build's module (setuptools writes its files there)
mkdir -p "$tmp/build/python/symrep"
ln -s "$module" "$tmp/build/python/symrep/"

echo "== pip install --no-build-isolation --prefix $tmp/prefix $src"
SYMREP_CMAKE_BUILD_DIR=$tmp/build PIP_DISABLE_PIP_VERSION_CHECK=1 PYTHONDONTWRITEBYTECODE=1 \
    "$python" -m pip install --no-build-isolation --no-index --no-deps --no-cache-dir --no-compile \
    --no-warn-script-location --root-user-action=ignore --prefix "$tmp/prefix" "$src" > "$tmp/pip.log" 2>&1 || {
    cat "$tmp/pip.log"
    fail "pip install"
}
# where this pip put it (Debian's pip: PREFIX/local/lib/python3.X/dist-packages)
init=$(find "$tmp/prefix" -path '*/symrep/__init__.py' -print -quit)
[[ -n $init ]] || fail "pip installed no symrep/__init__.py under $tmp/prefix"
site=$(dirname "$(dirname "$init")")
kernels=$(find "$tmp/prefix" -path '*/share/jupyter/kernels/symrep' -type d -print -quit)
[[ -n $kernels ]] || fail "pip installed no share/jupyter/kernels/symrep under $tmp/prefix"
# the sources are left as they were: setuptools' files went to $tmp/build/pip
[[ ! -e $src/build-pip && ! -e $src/repl/python/symrep.egg-info ]] || fail "pip wrote into the source tree"

"$python" "$src/tests/install/check_python_package.py" "$site" "$kernels" "$src" "$build" || exit 1

# the metadata: version, licence, the Pygments lexer's entry point (symrep.lexer:SymrepLexer)
"$python" -I -S - "$site" "$src" << 'EOF_PY' || fail "the package metadata"
import re, sys
sys.path.append(sys.argv[1])
from importlib import metadata
version = re.search(r"project\(\s*symrep\s+VERSION\s+([0-9.]+)", open(sys.argv[2] + "/CMakeLists.txt").read()).group(1)
m = metadata.metadata("symrep")
assert m["Version"] == version, (m["Version"], version)
assert m["License"] == "GPL-2.0-or-later", m["License"]
assert "License :: OSI Approved :: GNU General Public License v2 or later (GPLv2+)" in m.get_all("Classifier")
eps = [e for e in metadata.entry_points(group="pygments.lexers") if e.name == "symrep"]
assert [e.value for e in eps] == ["symrep.lexer:SymrepLexer"], eps
assert any(str(f).endswith("LICENSE") for f in metadata.files("symrep")), "no LICENSE in the distribution"
print("metadata: symrep %s, %s, pygments.lexers: symrep = %s" % (m["Version"], m["License"], eps[0].value))
EOF_PY
echo "test_pip: all checks passed"

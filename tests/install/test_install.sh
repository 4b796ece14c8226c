#!/usr/bin/env bash
# tests/install/test_install.sh BUILD_DIR SOURCE_DIR -- the installed package, as a user meets it
# (ctest: install.package; docs/library.md).
#
# Installs the built engine into a temporary prefix (cmake --install BUILD_DIR --prefix ...),
# checks what is there (headers under include/symrep reached as <symrep/...> with PREFIX/include
# the only include root, symrep/version.h, libraries, rules, the CMake package symrepConfig.cmake
# and symrepConfigVersion.cmake, the pkg-config file; with the Python module: the Python package
# and the Jupyter kernel spec, through check_python_package.py) and what is not (the internal
# headers, paths of the source or build tree), then builds examples/cpp
# against that prefix -- not against the build tree -- with find_package(symrep), runs both
# programs, builds one of them again with pkg-config, and checks that a program finds the
# installed rule files. Temporary folders are removed on exit. $CMAKE and $CXX choose cmake and
# the compiler (ctest passes the build's own; default: cmake and g++ on PATH); $SYMREP_TEST_PYTHON
# (set by ctest when the module is built) the interpreter that checks the Python package.
set -euo pipefail

if [[ $# -ne 2 ]]; then
    echo "usage: $0 BUILD_DIR SOURCE_DIR" >&2
    exit 2
fi
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
cmake_bin=${CMAKE:-cmake}
cxx=${CXX:-g++}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/symrep-install-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

fail() {
    echo "test_install: FAILED: $*" >&2
    exit 1
}
step() { echo "== $*"; }

# the Python package goes to PREFIX/SYMREP_PYTHON_INSTALL_DIR: relative, or it would not land in
# the temporary prefix
python_dir=$(sed -n 's/^SYMREP_PYTHON_INSTALL_DIR:[A-Z]*=//p' "$build/CMakeCache.txt")
if [[ -n ${SYMREP_TEST_PYTHON:-} && $python_dir == /* ]]; then
    fail "SYMREP_PYTHON_INSTALL_DIR=$python_dir is absolute: this test installs into a temporary prefix only"
fi

step "cmake --install $build --prefix $prefix"
"$cmake_bin" --install "$build" --prefix "$prefix" > "$tmp/install.log" || {
    cat "$tmp/install.log"
    fail "cmake --install"
}

# --- what is installed -------------------------------------------------------------------------
# the include root is PREFIX/include: headers are reached as <symrep/<part>/x.h>
incroot=$prefix/include
inc=$incroot/symrep
engine_lib=$(find "$prefix" -name libsymrep_engine.a -print -quit)
[[ -n $engine_lib ]] || fail "libsymrep_engine.a is not installed"
libdir=$(dirname "$engine_lib")
for f in "$libdir/libsymrep_interrupt.a" \
         "$libdir/cmake/symrep/symrepConfig.cmake" \
         "$libdir/cmake/symrep/symrepConfigVersion.cmake" \
         "$libdir/cmake/symrep/symrepTargets.cmake" \
         "$libdir/pkgconfig/symrep.pc" \
         "$prefix/share/symrep/rules/vector.rules" \
         "$inc/core/error.h" "$inc/core/interrupt.h" "$inc/algebra/element.h" \
         "$inc/algebra/multicomplex.h" "$inc/mechanics/cauchy_problem.h" "$inc/mechanics/operator_ode.h" \
         "$inc/numeric/verify.h" "$inc/output/printer.h" "$inc/vector/vector.h" "$inc/lang/interpreter.h" \
         "$inc/version.h"; do
    [[ -f $f ]] || fail "not installed: ${f#"$prefix"/}"
done
# the program, run from the prefix: it answers and finds the installed rules (SYMREP_RULES_DIR as
# the docs say for a prefix other than the configured one)
[[ -x $prefix/bin/symrep ]] || fail "not installed: bin/symrep"
out=$(SYMREP_RULES_DIR=$prefix/share/symrep/rules "$prefix/bin/symrep" -e 'vector a, b; rewrite(a x (a x b))' 2>&1) ||
    fail "bin/symrep -e ... failed: $out"
[[ $out == "(a . b)*a - |a|^2*b" ]] || fail "bin/symrep gave: $out"
echo "installed: $(find "$inc" -name '*.h' | wc -l) headers," \
     "$(find "$libdir" -maxdepth 1 -name 'libsymrep_*.a' | wc -l) libraries," \
     "$(find "$prefix/share/symrep/rules" -name '*.rules' | wc -l) rule file(s)"

# the implementation details stay out (CMakeLists.txt, SYMREP_INTERNAL_HEADERS)
for h in vector/vector_internal.h algebra/sobrero_kernel.h algebra/walsh_kernel.h \
         algebra/multicomplex_transform.h algebra/multicomplex_indexing.h algebra/batched_exp.h \
         mechanics/residual_proof.h lang/statement_clock.h; do
    [[ ! -e $inc/$h ]] || fail "internal header installed: $h"
done
internal=$(find "$inc" -name '*_internal.h' -o -name '*_kernel.h')
[[ -z $internal ]] || fail "internal headers installed: $internal"
# every public header of the source tree is installed (or listed as internal above)
while IFS= read -r h; do
    rel=${h#"$src"/engine/}
    case $rel in
        vector/vector_internal.h | algebra/sobrero_kernel.h | algebra/walsh_kernel.h | \
        algebra/multicomplex_transform.h | algebra/multicomplex_indexing.h | algebra/batched_exp.h | \
        mechanics/residual_proof.h | lang/statement_clock.h) ;;
        *) [[ -f $inc/$rel ]] || fail "public header not installed: $rel" ;;
    esac
done < <(find "$src/engine" -mindepth 2 -maxdepth 2 -name '*.h' | sort)
# every "..." include of an installed header is installed too, under the include root
# PREFIX/include ("symrep/<part>/x.h"; not "<part>/x.h", which needs include/symrep on the path)
while IFS= read -r h; do
    while IFS= read -r dep; do
        [[ $dep == symrep/* ]] ||
            fail "${h#"$inc"/} includes \"$dep\", not \"symrep/...\" (tests/install/rewrite_includes.py)"
        [[ -f $incroot/$dep ]] || fail "${h#"$inc"/} includes \"$dep\", which is not installed"
    done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$h")
done < <(find "$inc" -name '*.h')
# symrep/version.h: the number of project(VERSION) in CMakeLists.txt
version=$(sed -n 's/^project(symrep VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
grep -q "^#define SYMREP_VERSION \"$version\"\$" "$inc/version.h" || fail "include/symrep/version.h does not say $version"
grep -q "^set(PACKAGE_VERSION \"$version\")\$" "$libdir/cmake/symrep/symrepConfigVersion.cmake" ||
    fail "symrepConfigVersion.cmake does not say $version"
[[ $("$prefix/bin/symrep" --version) == "symrep $version" ]] || fail "bin/symrep --version: $("$prefix/bin/symrep" --version)"
# the licence is named in the package files
grep -q "SPDX-License-Identifier: GPL-2.0-or-later" "$libdir/cmake/symrep/symrepConfig.cmake" ||
    fail "symrepConfig.cmake does not name the licence"
grep -q "SPDX-License-Identifier: GPL-2.0-or-later" "$libdir/pkgconfig/symrep.pc" || fail "symrep.pc does not name the licence"
# nothing of the source or build tree in the package files (relocatable, no SYMREP_SOURCE_DIR)
if grep -rlF -e "$src" -e "$build" "$libdir/cmake/symrep" "$libdir/pkgconfig/symrep.pc"; then
    fail "the package files above name the source or build tree"
fi

# --- the Python package and the kernel spec (when the module is built) ---------------------------
if [[ -n ${SYMREP_TEST_PYTHON:-} ]]; then
    step "the Python package in $prefix/$python_dir, the kernel spec in share/jupyter/kernels/symrep"
    "$SYMREP_TEST_PYTHON" "$src/tests/install/check_python_package.py" "$prefix/$python_dir" \
        "$prefix/share/jupyter/kernels/symrep" "$src" "$build" || fail "the installed Python package"
else
    echo "== no Python module in this build: the Python package is not checked"
fi

# --- examples/cpp with find_package(symrep) -----------------------------------------------------
step "examples/cpp against $prefix (find_package)"
"$cmake_bin" -S "$src/examples/cpp" -B "$tmp/examples" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release > "$tmp/configure.log" 2>&1 || {
    cat "$tmp/configure.log"
    fail "configuring examples/cpp"
}
grep -q "^symrep_DIR:PATH=$libdir/cmake/symrep\$" "$tmp/examples/CMakeCache.txt" ||
    fail "find_package(symrep) did not take the package in $prefix: $(grep '^symrep_DIR' "$tmp/examples/CMakeCache.txt")"
"$cmake_bin" --build "$tmp/examples" -j2 > "$tmp/build.log" 2>&1 || {
    cat "$tmp/build.log"
    fail "building examples/cpp"
}

run() {  # run NAME PROGRAM...: output in $tmp/NAME.out, fail on a nonzero exit
    local name=$1
    shift
    local status=0
    "$@" > "$tmp/$name.out" 2>&1 || status=$?
    if [[ $status -ne 0 ]]; then
        cat "$tmp/$name.out"
        fail "$name exited with $status"
    fi
}
expect_line() {  # expect_line NAME TEXT: the output of NAME has a line containing TEXT
    grep -qF -- "$2" "$tmp/$1.out" || {
        cat "$tmp/$1.out"
        fail "$1: no line with '$2'"
    }
}

step "foucault"
run foucault "$tmp/examples/foucault"
expect_line foucault "ok      check(P, s): residual 0, initial values met"
expect_line foucault "ok      s equals the thesis's form (VI.1.79)"
expect_line foucault "ok      Boost.Odeint (rkf78, tolerance 1e-12) against the closed form over one day"
expect_line foucault "all checks passed"
grep -v '^r(t) = ' "$tmp/foucault.out"
# symrep::interrupt linked: the program defines its own operator new
if command -v nm > /dev/null; then
    nm -C "$tmp/examples/foucault" > "$tmp/foucault.nm"  # (not piped into grep -q: pipefail)
    grep -qE ' T operator new\(unsigned long\)$' "$tmp/foucault.nm" ||
        fail "foucault does not define operator new (symrep::interrupt not linked)"
fi

step "multicomplex"
run multicomplex "$tmp/examples/multicomplex"
expect_line multicomplex "ok      w * inverse(w) = 1"
expect_line multicomplex "ok      minpoly(w)(w) = 0"
expect_line multicomplex "ok      d/dt exp(w t) = w exp(w t) and exp(w 0) = 1"
expect_line multicomplex "ok      inverse(1 + i0*i1) is refused"
expect_line multicomplex "ok      z * inverse(z) = 1 in multicomplex(2)"
expect_line multicomplex "all checks passed"
grep '^ok\|FAILED\|^all' "$tmp/multicomplex.out"

# --- pkg-config -----------------------------------------------------------------------------------
if command -v pkg-config > /dev/null; then
    export PKG_CONFIG_PATH=$libdir/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}
    step "multicomplex with pkg-config: $(pkg-config --cflags --libs symrep)"
    [[ $(pkg-config --modversion symrep) == "$version" ]] || fail "pkg-config's version is not $version"
    # (the relocatable prefix is spelled through ${pcfiledir}/../..: compare the folders themselves)
    pc_includes=$(for flag in $(pkg-config --cflags-only-I symrep); do realpath -m "${flag#-I}"; done)
    grep -qxF "$(realpath "$incroot")" <<< "$pc_includes" && ! grep -qxF "$(realpath "$inc")" <<< "$pc_includes" ||
        fail "pkg-config's include path is not PREFIX/include alone: $(pkg-config --cflags-only-I symrep)"
    # shellcheck disable=SC2046  # the flags are words
    "$cxx" -std=c++20 -O1 "$src/examples/cpp/multicomplex.cpp" -o "$tmp/multicomplex_pc" \
        $(pkg-config --cflags --libs symrep) || fail "compiling multicomplex.cpp with pkg-config"
    run multicomplex_pc "$tmp/multicomplex_pc"

    # every installed header, in one translation unit, as a user includes it (<symrep/...>) with
    # the package's flags only (each one alone costs a minute on two cores; together they take
    # seconds)
    (cd "$incroot" && find symrep -name '*.h' | sort | sed 's|.*|#include <&>|') > "$tmp/all_headers.cpp"
    # shellcheck disable=SC2046
    "$cxx" -std=c++20 -fsyntax-only "$tmp/all_headers.cpp" $(pkg-config --cflags symrep) ||
        fail "the installed headers do not compile together with pkg-config's flags"
    expect_line multicomplex_pc "all checks passed"
    diff <(grep '^ok\|FAILED' "$tmp/multicomplex.out") <(grep '^ok\|FAILED' "$tmp/multicomplex_pc.out") ||
        fail "the pkg-config build reports other checks than the CMake build"

    # the installed rule files: a program reads them from the folder the package names
    # (pkg-config's rulesdir, CMake's symrep_RULES_DIR; SYMREP_RULES_DIR at run time, since this
    # prefix is not the one the library was configured with, see rules/rules.h)
    rulesdir=$(pkg-config --variable=rulesdir symrep)
    [[ -f $rulesdir/vector.rules ]] || fail "pkg-config's rulesdir $rulesdir has no vector.rules"
    cat > "$tmp/rules_check.cpp" << 'EOF'
#include <iostream>
#include <symrep/core/error.h>
#include <symrep/rules/rules.h>
int main() {
    try {
        const auto& r = symrep::rules::default_rules();
        std::cout << symrep::rules::default_rules_dir() << ": " << r.rules().size() << " rules\n";
        return r.rules().empty() ? 1 : 0;
    } catch (const symrep::error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}
EOF
    step "the installed rules"
    # shellcheck disable=SC2046
    "$cxx" -std=c++20 -O0 "$tmp/rules_check.cpp" -o "$tmp/rules_check" $(pkg-config --cflags --libs symrep) ||
        fail "compiling the rules check with pkg-config"
    run rules_check env SYMREP_RULES_DIR="$rulesdir" "$tmp/rules_check"
    cat "$tmp/rules_check.out"
    expect_line rules_check "$rulesdir: "
    # and a folder without rules is an error, not an empty rule set
    mkdir "$tmp/no_rules"
    if SYMREP_RULES_DIR="$tmp/no_rules" "$tmp/rules_check" > /dev/null 2>&1; then
        fail "the rules check succeeds without rule files"
    fi
else
    echo "== pkg-config not found: the pkg-config build is skipped"
fi

echo "test_install: all checks passed"

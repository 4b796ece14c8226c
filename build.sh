#!/usr/bin/env bash
# symrep set-up, build and run. Usage (as root on Debian, from anywhere):
#   bash build.sh main   install what is missing, build, run the main derivation script
#   bash build.sh test   install what is missing, build, run every test (ctest), then the
#                        robustness test under AddressSanitizer + LeakSanitizer (10000 inputs)
#   bash build.sh deps   only install the Debian packages that are missing
#   bash build.sh build  deps + build only (with the benchmarks; test builds none)
#   bash build.sh fuzz [N]  the robustness run under AddressSanitizer + UBSan:
#                        N random and mutated inputs (default 100000; docs/testing.md)
#   bash build.sh docs   deps + the program and the Python module, then the documentation
#                        site (Sphinx, warnings are errors) into BUILD_DIR/docs/html
# Environment: BUILD_DIR (default: build), ASAN_BUILD_DIR (default: BUILD_DIR-asan),
# SANITIZE_BUILD_DIR (fuzz; default: BUILD_DIR-sanitize), JOBS (default: number of cores + 1).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

BUILD_DIR=${BUILD_DIR:-build}
# one job more than cores: a link (single-threaded) or a wait on the disk leaves no core idle
JOBS=${JOBS:-$(( $(nproc 2>/dev/null || echo 2) + 1 ))}
ASAN_BUILD_DIR=${ASAN_BUILD_DIR:-$BUILD_DIR-asan}            # test: AddressSanitizer (+ LeakSanitizer)
SANITIZE_BUILD_DIR=${SANITIZE_BUILD_DIR:-$BUILD_DIR-sanitize}  # fuzz: AddressSanitizer and UBSan
MAIN_SCRIPT=examples/foucault.symrep

# What the program needs to build and run the main script (bash build.sh main installs only these)
MAIN_PACKAGES=(g++ make cmake pkg-config
          libginac-dev libcln-dev libeigen3-dev libboost-dev libreadline-dev gnuplot-nox)
# and what the tests, the benchmarks, the Python module, the notebooks and the docs need
PACKAGES=("${MAIN_PACKAGES[@]}"
          libgtest-dev libgmock-dev libbenchmark-dev tmux
          # the Python module, the Jupyter kernel and the Dask example (docs/python.md)
          pybind11-dev python3-dev python3-numpy python3-pytest python3-sympy
          python3-ipykernel python3-jupyter-client python3-nbformat python3-nbconvert
          python3-dask python3-distributed
          # the notebooks in a browser: the `jupyter notebook` command, MathJax for the
          # notebook and the exported HTML (offline), the browser test (tests/browser)
          python3-notebook jupyter-notebook jupyter-nbconvert python3-nbclient libjs-mathjax
          chromium chromium-driver python3-selenium
          # progress: the tqdm bar (optional at run time) and script(1) for the terminal test (docs/progress.md)
          python3-tqdm bsdutils
          # the documentation site (bash build.sh docs; docs/build_site.py)
          python3-sphinx python3-myst-parser python3-nbsphinx python3-sphinx-rtd-theme pandoc
          # pip install . (pyproject.toml, setup.py; offline: --no-build-isolation) and its test
          python3-setuptools python3-pip)

# deps [PACKAGE...]: install those of the packages (default: all of PACKAGES) that are missing
deps() {
    local missing=() wanted=("$@")
    [ ${#wanted[@]} -eq 0 ] && wanted=("${PACKAGES[@]}")
    for p in "${wanted[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "symrep: installing ${missing[*]}" >&2
    if [ "$(id -u)" -ne 0 ]; then
        echo "symrep: missing Debian packages (${missing[*]}); run as root or install them" >&2
        exit 1
    fi
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# build [TARGET...]: configure and build the named targets (default: all of them: the program,
# the tests, the benchmarks and the Python module). The main job builds only the program
# (build_main: configured without the tests, benchmarks and module, whose packages it does
# not install; a later `build` turns them on again in the same build directory).
build_main() {
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DSYMREP_BUILD_TESTS=OFF -DSYMREP_BUILD_BENCH=OFF \
          -DSYMREP_BUILD_PYTHON=OFF >/dev/null
    cmake --build "$BUILD_DIR" -j"$JOBS" --target symrep
}
# build [TARGET...]: the program, the tests and the module; the benchmarks too unless BENCH=OFF
# (bash build.sh test: benchmarks are not tests, and their -O3 build took a minute of the CI budget;
# bash build.sh build and the bench/ scripts build them)
build() {
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DSYMREP_BUILD_TESTS=ON -DSYMREP_BUILD_BENCH="${BENCH:-ON}" \
          -DSYMREP_BUILD_PYTHON=ON >/dev/null
    local targets=()
    for t in "$@"; do targets+=(--target "$t"); done
    cmake --build "$BUILD_DIR" -j"$JOBS" "${targets[@]}"
}

# The robustness test (tests/test_robustness.cpp; docs/testing.md) built with
# -DSYMREP_SANITIZE=ON, on $1 inputs (default: its own, 10000): a crash, a
# sanitizer report or a runaway statement fails it.
# sanitized_robustness SANITIZERS DIR [LINES]: the robustness run built with -fsanitize=SANITIZERS
sanitized_robustness() {
    cmake -S . -B "$2" -DCMAKE_BUILD_TYPE=Release -DSYMREP_SANITIZE=ON -DSYMREP_SANITIZERS="$1" \
          -DSYMREP_BUILD_BENCH=OFF -DSYMREP_BUILD_PYTHON=OFF >/dev/null
    cmake --build "$2" -j"$JOBS" --target symrep_robustness
    SYMREP_FUZZ_LINES=${3:-} "$2"/symrep_robustness
}

case "${1:-}" in
    deps)  deps ;;
    build) deps; build ;;
    main)  deps "${MAIN_PACKAGES[@]}"; build_main; "$BUILD_DIR"/symrep "$MAIN_SCRIPT" ;;
    test)  deps; BENCH=OFF build; ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$JOBS"
           sanitized_robustness address "$ASAN_BUILD_DIR" ;;
    fuzz)  deps; sanitized_robustness address,undefined "$SANITIZE_BUILD_DIR" "${2:-100000}" ;;
    docs)  deps; build symrep _symrep; /usr/bin/python3 docs/build_site.py "$BUILD_DIR" ;;
    *) sed -n '2,13p' "$0" >&2; exit 2 ;;
esac

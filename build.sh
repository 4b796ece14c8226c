#!/usr/bin/env bash
# symrep set-up, build and run. Usage (as root on Debian, from anywhere):
#   bash build.sh main   install what is missing, build, run the main derivation script
#   bash build.sh test   install what is missing, build, run every test (ctest)
#   bash build.sh deps   only install the Debian packages that are missing
#   bash build.sh build  deps + build only
# Environment: BUILD_DIR (default: build), JOBS (default: number of cores).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
MAIN_SCRIPT=examples/foucault.symrep

PACKAGES=(g++ make cmake pkg-config
          libginac-dev libcln-dev libeigen3-dev libboost-dev
          libgtest-dev libgmock-dev libbenchmark-dev libreadline-dev gnuplot-nox tmux)

deps() {
    local missing=()
    for p in "${PACKAGES[@]}"; do
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

build() {
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$BUILD_DIR" -j"$JOBS"
}

case "${1:-}" in
    deps)  deps ;;
    build) deps; build ;;
    main)  deps; build; "$BUILD_DIR"/symrep "$MAIN_SCRIPT" ;;
    test)  deps; build; ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$JOBS" ;;
    *) sed -n '2,8p' "$0" >&2; exit 2 ;;
esac

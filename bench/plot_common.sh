# bench/plot_common.sh -- the set-up every bench/plot_*.sh shares, sourced by them:
# strict mode, the repository root as the working directory, $build (the script's first
# argument, default build) and $out (docs/figures, created).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=docs/figures
mkdir -p "$out"

#!/bin/sh
# Regenerates docs/language.md = docs/language.prose.md + `symrep --doc`.
# usage: docs/regen_language_md.sh [path/to/symrep]   (default build/symrep)
set -e
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-$here/../build/symrep}
{ cat "$here/language.prose.md"; "$bin" --doc; } > "$here/language.md"

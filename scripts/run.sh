#!/usr/bin/env bash
# The README's main command: set up (install what is missing, configure, build),
# then run Loom on the bundled default input (or on the surface given as $1).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
input="${1:-examples/schneiders.obj}"
out="build/demo"
echo "== loom stc $input --dot $out"
build/loom stc "$input" --dot "$out"

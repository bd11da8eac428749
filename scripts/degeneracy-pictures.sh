#!/usr/bin/env bash
# Redraws the pictures of docs/degeneracies.md: the degeneracy test cases
# write their states before and after as DOT, Graphviz renders them to SVG.
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/images/degeneracies
mkdir -p "$out"
cmake --build build --target test_degeneracies >/dev/null
LOOM_DOC_PICTURES="$out" build/tests/test_degeneracies >/dev/null
for f in "$out"/*.dot; do dot -Tsvg "$f" -o "${f%.dot}.svg"; done
echo "wrote $(ls "$out"/*.svg | wc -l) pictures into $out"

#!/usr/bin/env bash
# The README's main command: set up (install what is missing, configure, build),
# then weave the bundled default input (or the surface given as $1) into a hex
# mesh under build/demo/, check it, and draw its STC.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
input="${1:-examples/lshape-3.obj}"
out="build/demo"
mkdir -p "$out"
name="$(basename "${input%.*}")"
echo "== loom weave $input"
build/loom weave "$input" -o "$out/$name.vtk" --report "$out/$name.json" --dot "$out/$name-stc"
echo "== loom check $out/$name.vtk --boundary $input"
build/loom check "$out/$name.vtk" --boundary "$input"
echo "== wrote $out/$name.vtk (hex mesh), $out/$name.json (report), $out/$name-stc/ (STC and sheet diagrams)"

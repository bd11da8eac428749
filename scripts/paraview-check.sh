#!/usr/bin/env bash
# Writes three meshes with loom weave as .vtu and opens each in ParaView
# (scripts/paraview-check.py): a woven box, a cylinder with its boundary layer,
# and a searched random sphere with inverted hexes. Installs Debian's
# python3-paraview if it is missing (through scripts/setup.sh, which also
# builds). Not part of the test suite: ParaView is large (186 packages).
set -euo pipefail
cd "$(dirname "$0")/.."
LOOM_EXTRA_PACKAGES=python3-paraview bash scripts/setup.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() {
  local name=$1; shift
  build/loom gen "$@" -o "$work/$name.obj" >/dev/null
  # Status 3 (hexes <= 0) still writes the mesh: it is what the fields are for.
  build/loom weave "$work/$name.obj" -o "$work/$name.vtu" --report "$work/$name.json" -q || [ $? -eq 3 ]
  /usr/bin/python3 scripts/paraview-check.py "$work/$name.vtu" "$work/$name.json"
}
check box box 2 3 4
check cylinder cylinder 4 6
check randquad randquad 22 --seed 1

#!/usr/bin/env bash
# Rebuilds rules/closure/database.txt, the closure's database of small
# hexahedrizations (docs/closure.md): every mesh a shelling outwards from one
# hex reaches while its boundary has at most 24 quads, kept for boundaries of
# at most 18; then each entry's boundary is searched (2,000 expansions) and
# the entry keeps the smaller mesh the search finds. Deterministic: a rerun
# writes the same file. About 40 minutes and 2 GB on one core of the
# reference machine.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/bench/make_database --max-quads 24 --store-quads 18 --improve 2000 -o rules/closure/database.txt "$@"

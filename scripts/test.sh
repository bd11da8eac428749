#!/usr/bin/env bash
# The README's test command: set up (install what is missing, configure, build
# with STC invariant checks after every rewrite) and run every suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh -DLOOM_CHECK_INVARIANTS=ON
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600

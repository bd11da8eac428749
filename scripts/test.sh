#!/usr/bin/env bash
# The README's test command: set up (install what is missing, configure, build)
# and run every suite with ctest, which turns on the STC invariant checks after
# every rewrite (LOOM_CHECK_INVARIANTS=1, tests/CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600

#!/usr/bin/env bash
# Installs what Loom needs from Debian (only what is missing), then configures
# and builds into build/ (or $LOOM_BUILD_DIR). Used by the README's two commands,
# by .ci/run and by scripts/sanitize.sh (which builds into build-san/).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake ninja-build pkg-config libboost-graph-dev libfmt-dev doctest-dev
          libcli11-dev nlohmann-json3-dev libeigen3-dev libgraphviz-dev graphviz
          libgmsh-dev gmsh libnauty2-dev liblbfgspp-dev libexodusii-dev)
# Callers that need more name it (scripts/fuzz.sh: clang and libFuzzer).
read -r -a extra <<< "${LOOM_EXTRA_PACKAGES:-}"
packages+=("${extra[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Extra cmake arguments pass through.
build="${LOOM_BUILD_DIR:-build}"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${LOOM_BUILD_TYPE:-RelWithDebInfo}" "$@" >/dev/null
# $LOOM_BUILD_TARGETS (space-separated) builds only those, e.g. the fuzzers.
read -r -a targets <<< "${LOOM_BUILD_TARGETS:-}"
only=()
if ((${#targets[@]})); then only=(--target "${targets[@]}"); fi
cmake --build "$build" --parallel "$(nproc)" "${only[@]}"

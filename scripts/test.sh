#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (validation layer on).
# Usage: bash scripts/test.sh [default|asan]   (no argument: both, default first)
set -euo pipefail
cd "$(dirname "$0")/.."
presets=("$@")
[ ${#presets[@]} -gt 0 ] || presets=(default asan)
bash scripts/setup.sh
for preset in "${presets[@]}"; do
  echo "== preset ${preset}"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$(nproc)"
  # A test per core: lavapipe renders with every core, but much of the run is single-threaded
  # (shader compiles, fuzzers, JSON readers, process start-up).
  ctest --preset "$preset" -j "$(nproc)"
done

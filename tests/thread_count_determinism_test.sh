#!/usr/bin/env bash
# The same level and frames give bit-identical images run to run and with lavapipe on one
# thread or its default count (soft shadows and the denoiser included).
# Usage: thread_count_determinism_test.sh path/to/sightline path/to/level.json
set -euo pipefail
sightline=$1
level=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
render() {  # output file, then environment assignments
  local out=$1
  shift
  env "$@" "$sightline" render "$level" --size 64x36 --frames 8 --validate --out "$out" >/dev/null
}
render "$work/default.png"
render "$work/again.png"
render "$work/one_thread.png" LP_NUM_THREADS=1
cmp "$work/default.png" "$work/again.png" || { echo "FAIL: two runs differ"; exit 1; }
cmp "$work/default.png" "$work/one_thread.png" || {
  echo "FAIL: LP_NUM_THREADS=1 differs from the default thread count"
  exit 1
}
echo "8 frames of $(basename "$level"): identical across runs and thread counts"

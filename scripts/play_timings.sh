#!/usr/bin/env bash
# Plays every shipped level (or the given ones) for 600 ticks in a 1280x720 window under Xvfb
# and prints play's frame rate, percentiles, per-part medians and means and the dynamic render
# scale's range (PLAY_OPTIONS=--fixed-scale keeps the scale), and bench's frame rate for the same
# render size, without and with play's temporal upscaling, one level after the other
# (docs/PERFORMANCE.md).
# Usage: bash scripts/play_timings.sh [--binary PATH] [--capture-dir DIR] [-- play options]
set -euo pipefail
cd "$(dirname "$0")/.."
binary=./build/sightline
capture_dir=""
while [ $# -gt 0 ]; do
  case "$1" in
    --binary) binary="$2"; shift 2 ;;
    --capture-dir) capture_dir="$2"; shift 2 ;;
    --) shift; break ;;
    *) break ;;
  esac
done
levels=("$@")
[ ${#levels[@]} -gt 0 ] ||
  mapfile -t levels < <(sed 's/#.*//; /^[[:space:]]*chapter:/d; s/[[:space:]]//g; /^$/d; s|^|levels/|' levels/order.txt)
home=$(mktemp -d)  # no saved settings or progress
trap 'rm -rf "$home"' EXIT
for level in "${levels[@]}"; do
  name=$(basename "$level" .json)
  capture=()
  [ -z "$capture_dir" ] || { mkdir -p "$capture_dir"; capture=(--capture "$capture_dir/$name.png"); }
  echo "== $name"
  HOME="$home" xvfb-run -a -s "-screen 0 1280x720x24" "$binary" play "$level" \
    --quit-after-ticks 600 "${capture[@]}" ${PLAY_OPTIONS:-} 2>&1 |
    grep -E "^(playing|quit after|frame parts|window picture|picture scale)" || true
  "$binary" bench "$level" --frames 60 --embree-frames 0 --size 320x180 2>&1 |
    grep -E "^${name} " | head -1 | awk '{print "bench: " $4 " ms, " $5 " fps"}'  || true
  # What the window's picture costs before it is drawn into the window: on a CPU driver play
  # upscales temporally to half the 1280x720 window.
  "$binary" bench "$level" --frames 60 --embree-frames 0 --size 320x180 --upscale 640x360 2>&1 |
    grep -E "^${name} " | head -1 |
    awk '{print "bench --upscale 640x360: " $4 " ms, " $5 " fps"}' || true
done

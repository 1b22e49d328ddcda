#!/usr/bin/env bash
# The same replay gives a bit-identical per-tick trace (probe readings, goal progress, rules,
# player) run to run and with lavapipe on one thread or its default count: four replays, among
# them a level with rules (08) and one with light routed by a mirror and a colour sensor (09).
# Usage: replay_determinism_test.sh path/to/sightline path/to/replays
set -euo pipefail
sightline=$1
replays=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for replay in "$replays/01_first_light_win.json" "$replays/02_penumbra_win.json" \
  "$replays/08_workshop_win.json" "$replays/09_borrowed_light_win.json"; do
  name=$(basename "$replay" .json)
  "$sightline" replay "$replay" --trace "$work/$name.default.csv" >/dev/null
  "$sightline" replay "$replay" --trace "$work/$name.again.csv" >/dev/null
  LP_NUM_THREADS=1 "$sightline" replay "$replay" --trace "$work/$name.one_thread.csv" >/dev/null
  hash() { md5sum <"$1" | cut -d' ' -f1; }
  [ "$(hash "$work/$name.default.csv")" = "$(hash "$work/$name.again.csv")" ] ||
    { echo "FAIL: $name: two runs give different traces"; exit 1; }
  [ "$(hash "$work/$name.default.csv")" = "$(hash "$work/$name.one_thread.csv")" ] ||
    { echo "FAIL: $name: LP_NUM_THREADS=1 gives a different trace"; exit 1; }
  echo "$name: $(wc -l <"$work/$name.default.csv") trace lines, hash $(hash "$work/$name.default.csv") in all three runs"
done

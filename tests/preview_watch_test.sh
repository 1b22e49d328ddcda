#!/usr/bin/env bash
# `sightline preview --watch` re-renders when the level is saved, and an invalid edit keeps the
# last good level. Usage: preview_watch_test.sh path/to/sightline
set -euo pipefail
sightline=$1
work=$(mktemp -d)
pid=""
cleanup() {
  [ -n "$pid" ] && kill "$pid" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

write_level() {  # colour as JSON
  cat >"$work/level.json" <<JSON
{
  "format": 1, "name": "Watched",
  "camera": {"position": [0, 0.5, 3]},
  "environment": {"ambient": [1, 1, 1]},
  "materials": {"paint": {"color": $1}},
  "meshes": {"cube": {"box": {"size": [2, 2, 2]}}},
  "entities": {"cube": {"mesh": "cube", "material": "paint"}},
  "lights": {}
}
JSON
}

wait_for() {  # pattern in the log, or fail after 60 s
  for _ in $(seq 600); do
    grep -q "$1" "$work/log" && return 0
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  echo "FAIL: never saw '$1'; log:"
  cat "$work/log"
  exit 1
}

write_level '[1, 0, 0]'
"$sightline" preview "$work/level.json" --watch --watch-limit 2 --validate --size 32x18 \
  --out "$work/preview.png" >"$work/log" 2>&1 &
pid=$!
wait_for '^rendered Watched'
first=$(md5sum <"$work/preview.png")

sleep 0.05
write_level '[1, 0, 7]'  # out of range: reported, last good level kept
wait_for 'keeping the last good level'
grep -q 'level.json:5:' "$work/log" || { echo "FAIL: error lacks file:line"; cat "$work/log"; exit 1; }

sleep 0.05
write_level '[0, 0, 1]'
wait_for '^reloaded Watched'
status=0
wait "$pid" || status=$?
pid=""
second=$(md5sum <"$work/preview.png")
if [ "$status" -ne 0 ] || [ "$first" = "$second" ]; then
  echo "FAIL: exit status $status; image changed: $([ "$first" != "$second" ] && echo yes || echo no)"
  cat "$work/log"
  exit 1
fi
echo "preview --watch: rendered, kept the last good level on a bad edit, reloaded on a fix"

#!/usr/bin/env bash
# A run recorded in the window that wins (or loses) the level replays headless to the same
# outcome on the same tick. The levels end by themselves (a timer rule), so no input is needed,
# and none may be recorded: capturing the mouse in a 640x360 window once recorded a look of
# half the window at tick 0.
# Usage: record_outcome_test.sh path/to/sightline
set -uo pipefail
sightline=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data

fail() {
  echo "FAIL: $1"
  exit 1
}

for outcome in win lose; do
  cat >"$work/$outcome.json" <<JSON
{
  "format": 1, "name": "Timed $outcome",
  "camera": { "position": [0, 1.65, 4] },
  "materials": { "paint": {} },
  "meshes": { "floor": { "box": { "size": [10, 1, 10] } } },
  "entities": { "floor": { "mesh": "floor", "material": "paint", "position": [0, -0.5, 0] } },
  "lights": { "sun": { "type": "directional", "direction": [0.3, -1, -0.2], "intensity": 3 } },
  "logic": { "end": { "when": { "type": "timer", "seconds": 0.5 }, "then": [{ "do": "$outcome" }] } }
}
JSON
  env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 1280x720x24" \
    "$sightline" play "$work/$outcome.json" --window 640x360 --validate --quit-after-ticks 60 \
    --record "$work/$outcome.replay.json" >"$work/log" 2>&1 || { cat "$work/log"; fail "play ($outcome) failed"; }
  cat "$work/log"
  grep -qi "validation" "$work/log" && fail "validation messages (see above)"
  grep -q "^recorded 30 ticks of Timed $outcome" "$work/log" || fail "the $outcome was not recorded on tick 30"
  grep -q '"look"' "$work/$outcome.replay.json" && fail "a look was recorded with no mouse input"
  "$sightline" replay "$work/$outcome.replay.json" >"$work/log" 2>&1 || {
    cat "$work/log"
    fail "the recorded $outcome does not replay"
  }
  cat "$work/log"
  word=$([ "$outcome" = win ] && echo won || echo lost)
  grep -q "PASS $word on tick 30 " "$work/log" || fail "the recording replayed differently"
done
echo "PASS: recorded wins and losses replay to the same outcome on the same tick, with no look"

#!/usr/bin/env bash
# The level author's tools in `sightline play` under Xvfb, driven by xdotool: --author starts
# the fly camera, F6 copies the view as a level's camera block (and prints it), and saving the
# level reloads it in place with the player where they were; a save that does not load keeps
# the level as it was.
# Usage: play_author_test.sh path/to/sightline path/to/level.json
set -uo pipefail
sightline=$1
level=$2

for tool in xvfb-run xauth xdotool; do
  if ! command -v "$tool" >/dev/null; then
    echo "FAIL: $tool is not installed (scripts/setup.sh installs xvfb, xauth and xdotool)"
    exit 1
  fi
done
# A display of its own, which xvfb-run starts (and waits for) before running this script again.
if [ -z "${PLAY_AUTHOR_TEST_DISPLAY:-}" ]; then
  PLAY_AUTHOR_TEST_DISPLAY=1 exec env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 640x480x24" \
    bash "$0" "$@"
fi

work=$(mktemp -d)
export XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data
cp "$level" "$work/level.json"
log=$work/log
# A small picture, so that game time keeps up with real time.
trap 'kill "$game" 2>/dev/null; rm -rf "$work"' EXIT
"$sightline" play "$work/level.json" --author --validate --size 32x18 \
  --window 160x90 --no-upscale --quit-after-ticks 1500 >"$log" 2>&1 &
game=$!

fail() {
  cat "$log"
  echo "FAIL: $1"
  exit 1
}
# Waits up to 60 s for a line matching $1 in the log.
wait_for() {
  for _ in $(seq 600); do
    grep -q "$1" "$log" && return 0
    kill -0 "$game" 2>/dev/null || return 1
    sleep 0.1
  done
  return 1
}
wait_for "^playing " || fail "the level did not start"
window=$(xdotool search --sync --name Sightline | head -1)
[ -n "$window" ] || fail "no Sightline window"
key() { xdotool key --window "$window" "$1"; }

# Fly forwards and up for a second, then copy the view.
xdotool keydown --window "$window" w space
sleep 1
xdotool keyup --window "$window" w space
sleep 0.3
key F6
wait_for '^"camera": ' || fail "F6 printed no camera block"
before=$(grep '^"camera": ' "$log" | tail -1)
spawn_z=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['camera']['position'][2])" "$level")
python3 - "$before" "$spawn_z" <<'PY' || fail "the fly camera did not move the view: $before"
import json, sys
camera = json.loads("{" + sys.argv[1] + "}")["camera"]
# Forwards along the view and up: away from the spawn point by more than a metre.
assert abs(camera["position"][2] - float(sys.argv[2])) > 1.0 or camera["position"][1] > 2.5, camera
PY
grep -q '^"position": \[' "$log" || fail "F6 printed no position for the point under the crosshair"

# A broken save keeps the level; a good one reloads it with the player in place.
sed -i '1s/^{/{ oops/' "$work/level.json"
wait_for "(keeping the level as it was)" || fail "a broken save was not reported"
cp "$level" "$work/level.json"
python3 - "$work/level.json" <<'PY'
import json, sys
level = json.load(open(sys.argv[1]))
level["name"] = "Edited while playing"
json.dump(level, open(sys.argv[1], "w"), indent=1)
PY
wait_for "^reloaded .*: the rules start again, the player stays" || fail "the saved level was not reloaded"
wait_for "^playing Edited while playing " || fail "the reload did not load the edited level"
key F6
for _ in $(seq 100); do
  [ "$(grep -c '^"camera": ' "$log")" -ge 2 ] && break
  sleep 0.1
done
[ "$(grep -c '^"camera": ' "$log")" -ge 2 ] || fail "F6 after the reload printed no camera block"
after=$(grep '^"camera": ' "$log" | tail -1)
[ "$after" = "$before" ] || fail "the reload moved the player: before $before, after $after"
wait "$game"
status=$?
cat "$log"
[ "$status" -eq 0 ] || fail "sightline play exited with status $status"
grep -qi "validation" "$log" && fail "validation messages"
grep -q "^won \|^lost " "$log" && fail "the fly camera won or lost the level"
echo "PASS: fly camera, copy view and live reload"

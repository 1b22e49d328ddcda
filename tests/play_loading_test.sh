#!/usr/bin/env bash
# While a level loads (seconds the first time on a CPU driver, its pipelines compiling), the
# window says so, with the level's name and a bar of how far it got: the first level's, and
# once a level is won, the next one's. A campaign of two levels of its own (SIGHTLINE_DATA_DIR):
# the first wins by a timer rule, so no input is needed.
# Usage: play_loading_test.sh path/to/sightline path/to/source/directory
set -uo pipefail
sightline=$1
source_dir=$2

for tool in xvfb-run Xvfb xauth; do
  if ! command -v "$tool" >/dev/null; then
    echo "FAIL: $tool is not installed (scripts/setup.sh installs xvfb and xauth)"
    exit 1
  fi
done
system_python=/usr/bin/python3
[ -x "$system_python" ] || system_python=python3

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data
fail() {
  echo "FAIL: $1"
  exit 1
}

root=$work/root
mkdir -p "$root/levels"
ln -s "$source_dir/shaders" "$root/shaders"
ln -s "$source_dir/assets" "$root/assets"
printf 'timed_win.json\nsecond.json\n' >"$root/levels/order.txt"
level() {  # name, end rule's seconds
  cat <<JSON
{
  "format": 1, "name": "$1",
  "camera": { "position": [0, 1.65, 4] },
  "materials": { "paint": { "color": [0.8, 0.5, 0.3] } },
  "meshes": { "floor": { "box": { "size": [10, 1, 10] } }, "post": { "box": { "size": [1, 3, 1] } } },
  "entities": {
    "floor": { "mesh": "floor", "material": "paint", "position": [0, -0.5, 0] },
    "post": { "mesh": "post", "material": "paint", "position": [0, 1.5, 0] }
  },
  "lights": { "sun": { "type": "directional", "direction": [0.3, -1, -0.2], "intensity": 3 } },
  "logic": { "end": { "when": { "type": "timer", "seconds": $2 }, "then": [{ "do": "win" }] } }
}
JSON
}
level "Timed Win" 0.5 >"$root/levels/timed_win.json"
level "The Second" 100 >"$root/levels/second.json"

# Won at tick 30; the outcome shows for 2 s (no ticks pass), then the second level loads and
# plays the other 30 ticks.
SIGHTLINE_DATA_DIR=$root env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 1280x720x24" \
  "$sightline" play "$root/levels/timed_win.json" --window 640x360 --validate \
  --quit-after-ticks 60 --capture-loading "$work/loading" >"$work/log" 2>&1 ||
  { cat "$work/log"; fail "play failed"; }
cat "$work/log"
grep -qi "validation" "$work/log" && fail "validation messages (see above)"
grep -q "^captured the window (640x360) while Timed Win loaded (0 %) to " "$work/log" ||
  fail "no loading screen captured for the first level"
grep -q "^won Timed Win at tick 30" "$work/log" || fail "the first level was not won at tick 30"
grep -q "^captured the window (640x360) while The Second loaded (0 %) to " "$work/log" ||
  fail "no loading screen captured for the level after the win"
grep -Eq "^playing The Second \(.*\) at [0-9]+x[0-9]+.*; loaded in [0-9.]+ s$" "$work/log" ||
  fail "the second level did not start, or play did not say how long it loaded"

# The screen's own steps: 0 % once the level's file is read, 65 % once its simulation is made,
# then two of the three frames that prepare its pictures (77 %, 88 %); the last step's stays.
for name in "Timed Win" "The Second"; do
  steps=$(grep -o "while $name loaded ([0-9]* %)" "$work/log" | grep -o "[0-9]* %" | tr -d ' %' | paste -sd ' ')
  [ "$steps" = "0 65 77 88" ] || fail "$name's loading screen showed the steps '$steps', not '0 65 77 88'"
done

# Over black: the name and "Loading..." in white, centred at 0.42 of the height (the name twice
# the font's size), and under them the bar, 88 % of it sky blue (86, 180, 233), the rest its
# dark track (40, 40, 40), between 0.35 and 0.65 of the width.
"$system_python" - "$work/loading" <<'PY' || fail "the loading screens are not as expected"
import sys
from PIL import Image
for name in ("timed_win", "second"):
    image = Image.open(f"{sys.argv[1]}/{name}.png").convert("RGB")
    assert image.size == (640, 360), image.size
    above = set(image.crop((0, 0, 640, int(0.38 * 360))).getdata())
    band = list(image.crop((0, int(0.38 * 360), 640, int(0.75 * 360))).getdata())
    text = sum(1 for pixel in band if min(pixel) >= 200)
    rows = [y for y in range(int(0.38 * 360), int(0.75 * 360))
            if (86, 180, 233) in image.crop((0, y, 640, y + 1)).getdata()]
    assert rows, "no bar"
    blue = [x for y in rows for x in range(640) if image.getpixel((x, y)) == (86, 180, 233)]
    track = [x for y in rows for x in range(640) if image.getpixel((x, y)) == (40, 40, 40)]
    print(name, "text pixels", text, "bar from", min(blue), "to", max(blue), "track to", max(track))
    assert above == {(0, 0, 0)}, sorted(above)[:5]
    assert text >= 100, text
    filled = (max(blue) + 1 - 0.35 * 640) / (0.3 * 640)
    assert abs(min(blue) - 0.35 * 640) <= 1 and abs(filled - 0.883) <= 0.01, (min(blue), filled)
    assert abs(max(track) + 1 - 0.65 * 640) <= 1, max(track)
PY
echo "PASS: the window says which level is loading and how far it got, the first and the next after a win"

#!/usr/bin/env bash
# While a level loads (seconds the first time on a CPU driver, its pipelines compiling), the
# window says so: the first level's name and "Loading..." over black, and once a level is won,
# the next one's over the last picture, dimmed. A campaign of two levels of its own
# (SIGHTLINE_DATA_DIR): the first wins by a timer rule, so no input is needed.
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
grep -q "^captured the window (640x360) while Timed Win loaded to " "$work/log" ||
  fail "no loading screen captured for the first level"
grep -q "^won Timed Win at tick 30" "$work/log" || fail "the first level was not won at tick 30"
grep -q "^captured the window (640x360) while The Second loaded to " "$work/log" ||
  fail "no loading screen captured for the level after the win"
grep -Eq "^playing The Second \(.*\) at [0-9]+x[0-9]+.*; loaded in [0-9.]+ s$" "$work/log" ||
  fail "the second level did not start, or play did not say how long it loaded"

# The text is white, centred at 0.42 of the height; the name is drawn twice the font's size.
"$system_python" - "$work/loading" <<'PY' || fail "the loading screens are not as expected"
import sys
from PIL import Image
folder = sys.argv[1]
first = Image.open(f"{folder}/timed_win.png").convert("RGB")
second = Image.open(f"{folder}/second.png").convert("RGB")
assert first.size == second.size == (640, 360), (first.size, second.size)
def text_pixels(image):
    band = image.crop((0, int(0.38 * 360), 640, int(0.62 * 360)))
    return sum(1 for pixel in band.getdata() if min(pixel) >= 200)
def picture_colours(image):  # above the text
    return set(image.crop((0, 0, 640, int(0.35 * 360))).getdata())
print("first: text pixels", text_pixels(first), "colours above it", len(picture_colours(first)))
print("second: text pixels", text_pixels(second), "colours above it", len(picture_colours(second)))
# The first level's: black but for the words.
assert picture_colours(first) == {(0, 0, 0)}, sorted(picture_colours(first))[:5]
assert text_pixels(first) >= 100, text_pixels(first)
# The second's: the first level's last picture behind the words, dimmed to at most 26 % of its
# brightness (black at 190/255 over it).
above = picture_colours(second)
assert len(above) >= 20, len(above)
assert max(max(pixel) for pixel in above) <= 70, max(max(pixel) for pixel in above)
assert text_pixels(second) >= 100, text_pixels(second)
PY
echo "PASS: the window says a level is loading, over black first and over the last picture after a win"

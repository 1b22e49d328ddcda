#!/usr/bin/env bash
# `sightline play` under Xvfb: the window opens with a swapchain, the level renders and is
# presented, and --quit-after-ticks exits cleanly with no validation message; the run recorded
# with --record replays headless to the same outcome.
# Usage: play_window_test.sh path/to/sightline path/to/level.json
set -uo pipefail
sightline=$1
level=$2

# No Xvfb means this test cannot say anything about the window: fail, and say why.
for tool in xvfb-run Xvfb xauth; do
  if ! command -v "$tool" >/dev/null; then
    echo "FAIL: $tool is not installed, so the window cannot be tested (scripts/setup.sh installs xvfb and xauth)"
    exit 1
  fi
done

# The pictures are read with Debian's python3-pil (scripts/setup.sh), which the system's Python
# has where another python3 may come first on the PATH.
system_python=/usr/bin/python3
[ -x "$system_python" ] || system_python=python3

log=$(mktemp)
recording=$(mktemp --suffix=.json)
home=$(mktemp -d)  # settings and progress of this test only
capture_dir=$(mktemp -d)
trap 'rm -rf "$log" "$recording" "$home" "$capture_dir"' EXIT
export XDG_CONFIG_HOME=$home/config XDG_DATA_HOME=$home/data
# The test's own display, even when one is set: no window on a developer's screen.
env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 1280x720x24" \
  "$sightline" play "$level" --validate --quit-after-ticks 30 --record "$recording" \
  --capture "$capture_dir/hud_30.png" >"$log" 2>&1
status=$?
cat "$log"

fail() {
  echo "FAIL: $1"
  exit 1
}
grep -q "xvfb-run: error" "$log" && fail "Xvfb could not be started here (see above)"
[ "$status" -eq 0 ] || fail "sightline play exited with status $status"
grep -q "^window: 1280x720, swapchain " "$log" || fail "no 'window: 1280x720, swapchain ...' line: the window did not open"
# A CPU driver uploads each image through the X connection: the surface has one of its own,
# so that the upload does not hold up GLFW's event polling (render/window_surface.hpp).
if grep -q "^window: .* on llvmpipe" "$log"; then
  grep -Eq "^window: .*, presenting over its own X connection(,|$)" "$log" ||
    fail "on lavapipe the surface does not have an X connection of its own"
fi
grep -q "^quit after 30 ticks" "$log" || fail "the scripted quit after 30 ticks did not happen"
grep -q "^quit after 30 ticks, 0 frames shown" "$log" && fail "no frame was presented"
grep -qi "validation" "$log" && fail "validation messages (see above)"
grep -q "headless" "$log" && fail "play fell back to a headless render"
grep -q "^recorded 30 ticks of " "$log" || fail "no recording was written"
"$sightline" replay "$recording" >"$log" 2>&1 || { cat "$log"; fail "the recording does not replay"; }
cat "$log"
grep -q "PASS neither won nor lost in 30 ticks" "$log" || fail "the recording replayed differently"

# The HUD is drawn over the picture in its own colours: the crosshair's white at the window's
# centre, the goal bar's shade (40, 40, 40) near its right end (play/hud.cpp: the bar spans
# 0.02-0.38 of the width, 0.93-0.955 of the height; the goal is not met at tick 30), and the
# picture around them.
"$system_python" - "$capture_dir/hud_30.png" <<'PY' || fail "the HUD is not drawn as expected over the picture"
import sys
from PIL import Image
image = Image.open(sys.argv[1]).convert("RGB")
assert image.size == (1280, 720), image.size
centre, bar_end = image.getpixel((640, 360)), image.getpixel((int(0.37 * 1280), int(0.9425 * 720)))
print("crosshair", centre, "goal bar", bar_end)
assert centre == (255, 255, 255), centre
assert bar_end == (40, 40, 40), bar_end
assert len(set(image.crop((0, 0, 400, 300)).getdata())) > 50, "no picture behind the HUD"
PY

# The window's image at tick 40 matches the headless render of the same tick: the run is
# recorded, the capture becomes the recording's image checkpoint, and `sightline replay`
# renders tick 40 headless and compares (pixels off by more than 2/255: at most 0.5 %). The
# window is the picture's size with the HUD off and no temporal upscaling (whose jittered rays a
# single headless frame does not have), so the draw samples each texel at its centre, one to one;
# the first run played the default, upscaled picture with validation on.
env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 1280x720x24" \
  "$sightline" play "$level" --validate --size 320x180 --window 320x180 --hud-off --no-upscale \
  --quit-after-ticks 40 --capture "$capture_dir/window_40.png" \
  --record "$capture_dir/run.json" >"$log" 2>&1 || { cat "$log"; fail "the capture run failed"; }
cat "$log"
grep -q "^window: 320x180, swapchain " "$log" || fail "the window is not 320x180"
grep -q "^captured the window (320x180) at tick 40 to " "$log" || fail "no capture at tick 40"
grep -qi "validation" "$log" && fail "validation messages in the capture run (see above)"
python3 - "$capture_dir/run.json" <<'PY' || fail "could not add the image checkpoint"
import json, sys
path = sys.argv[1]
replay = json.load(open(path))
# Checkpoints are checked on ticks 0..ticks-1: one tick more reaches tick 40 itself.
replay["ticks"] = 41
replay["expect"]["images"] = [{"tick": 40, "png": "window_40.png", "max_different_share": 0.005}]
json.dump(replay, open(path, "w"), indent=1)
PY
"$sightline" replay "$capture_dir/run.json" --validate >"$log" 2>&1 || {
  cat "$log"
  fail "the window's image at tick 40 differs from the headless render of tick 40"
}
cat "$log"

# A window wider than the picture: black bars left and right, the picture between them.
env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 1280x720x24" \
  "$sightline" play "$level" --validate --size 320x180 --window 400x180 --hud-off --no-upscale \
  --quit-after-ticks 5 --capture "$capture_dir/bars_5.png" >"$log" 2>&1 ||
  { cat "$log"; fail "the run in a wider window failed"; }
grep -qi "validation" "$log" && { cat "$log"; fail "validation messages in the wider window"; }
"$system_python" - "$capture_dir/bars_5.png" <<'PY' || fail "no black bars beside the picture"
import sys
from PIL import Image
image = Image.open(sys.argv[1]).convert("RGB")
assert image.size == (400, 180), image.size
for x0, x1 in ((0, 40), (360, 400)):
    bar = set(image.crop((x0, 0, x1, 180)).getdata())
    assert bar == {(0, 0, 0)}, (x0, sorted(bar)[:5])
assert len(set(image.crop((40, 0, 360, 180)).getdata())) > 50, "no picture between the bars"
PY

# On a CPU driver the CPU doubles a picture that fills the window at twice its size; the render
# pass that samples it (GPUs, and --window-pass) must show the same picture, to within rounding.
for path in host pass; do
  flag=()
  [ "$path" = pass ] && flag=(--window-pass)
  env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 1280x720x24" \
    "$sightline" play "$level" --validate --size 320x180 --window 640x360 --hud-off --no-upscale \
    --quit-after-ticks 40 --capture "$capture_dir/doubled_$path.png" "${flag[@]}" >"$log" 2>&1 ||
    { cat "$log"; fail "the doubled picture's run ($path) failed"; }
  grep -qi "validation" "$log" && { cat "$log"; fail "validation messages in the doubled picture's run ($path)"; }
  if [ "$path" = host ] && grep -q "^window: .* on llvmpipe" "$log"; then
    grep -Eq "^window picture: scaled by the CPU in ([0-9]+) of \1 frames shown$" "$log" ||
      { cat "$log"; fail "on lavapipe the CPU did not scale every frame's picture"; }
  fi
  if [ "$path" = pass ]; then
    grep -Eq "^window picture: scaled by the CPU in [1-9]" "$log" &&
      { cat "$log"; fail "with --window-pass the CPU scaled the picture"; }
  fi
done
"$system_python" - "$capture_dir/doubled_host.png" "$capture_dir/doubled_pass.png" <<'PY' ||
import sys
from PIL import Image
host, drawn = (Image.open(path).convert("RGB") for path in sys.argv[1:3])
assert host.size == drawn.size == (640, 360), (host.size, drawn.size)
worst = max(abs(a - b) for p, q in zip(host.getdata(), drawn.getdata()) for a, b in zip(p, q))
print("doubled on the CPU against the render pass: largest difference", worst, "of 255")
assert worst <= 2, worst
assert len(set(host.getdata())) > 50, "no picture"
PY
  fail "the picture the CPU doubled differs from the render pass's"

# A window a pixel or two from twice the picture's size (1366x768 at the default scale gives a
# 684x384 picture): the CPU still doubles it, centred, cut at the window's edges or with a
# black edge; the same pixels as in the 640x360 window.
for window in 642x362 638x358; do
  env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 1280x720x24" \
    "$sightline" play "$level" --validate --size 320x180 --window "$window" --hud-off \
    --no-upscale --quit-after-ticks 40 --capture "$capture_dir/near_$window.png" >"$log" 2>&1 ||
    { cat "$log"; fail "the run in a $window window failed"; }
  grep -qi "validation" "$log" && { cat "$log"; fail "validation messages in the $window window"; }
  if grep -q "^window: .* on llvmpipe" "$log"; then
    grep -Eq "^window picture: scaled by the CPU in ([0-9]+) of \1 frames shown$" "$log" ||
      { cat "$log"; fail "on lavapipe the CPU did not scale the picture in a $window window"; }
  fi
done
if grep -q "^window: .* on llvmpipe" "$log"; then
  "$system_python" - "$capture_dir" <<'PY' || fail "the picture in a window near twice its size is not the doubled picture"
import sys
from PIL import Image
folder = sys.argv[1]
exact = Image.open(f"{folder}/doubled_host.png").convert("RGB")
wider = Image.open(f"{folder}/near_642x362.png").convert("RGB")
narrower = Image.open(f"{folder}/near_638x358.png").convert("RGB")
assert wider.size == (642, 362) and narrower.size == (638, 358), (wider.size, narrower.size)
assert list(wider.crop((1, 1, 641, 361)).getdata()) == list(exact.getdata()), "padded picture"
edge = set(wider.crop((0, 0, 642, 1)).getdata()) | set(wider.crop((0, 0, 1, 362)).getdata())
edge |= set(wider.crop((0, 361, 642, 362)).getdata()) | set(wider.crop((641, 0, 642, 362)).getdata())
assert edge == {(0, 0, 0)}, sorted(edge)[:5]
assert list(narrower.getdata()) == list(exact.crop((1, 1, 639, 359)).getdata()), "cut picture"
print("a window a pixel wider or narrower a side shows the doubled picture, centred")
PY
fi

# Saved progress picks the first level not yet won; saved settings turn vsync off.
mkdir -p "$XDG_DATA_HOME/sightline" "$XDG_CONFIG_HOME/sightline"
echo '{"progress": 1, "completed": ["01_first_light.json"]}' >"$XDG_DATA_HOME/sightline/progress.json"
echo '{"settings": 1, "vsync": false}' >"$XDG_CONFIG_HOME/sightline/settings.json"
env -u WAYLAND_DISPLAY xvfb-run -a -s "-screen 0 1280x720x24" \
  "$sightline" play --validate --quit-after-ticks 5 >"$log" 2>&1 || { cat "$log"; fail "second run failed"; }
cat "$log"
grep -q "^playing Glass and Mirrors " "$log" || fail "with level 1 won, play did not start at the second level of levels/order.txt"
grep -q "^window: .* FIFO," "$log" && fail "vsync off in the settings, but the swapchain is FIFO"
echo "PASS"

#!/usr/bin/env bash
# The command line: `<command> --help` prints that command's options only, an option a command
# does not take and an unknown one are refused (with the nearest known one), and --version
# names the version and the Vulkan device; a soft-shadow level renders settled by default.
# Usage: command_line_test.sh path/to/sightline
set -uo pipefail
sightline=$1
fail() {
  echo "FAIL: $1"
  exit 1
}

help=$("$sightline" render --help) || fail "render --help exited with $?"
[[ "$help" == "usage: sightline render <level.json> [options]"* ]] || fail "render --help: $help"
grep -q -- "--frames N" <<<"$help" || fail "render --help does not list --frames"
grep -q -- "--record" <<<"$help" && fail "render --help lists --record, a play option"
[ "$(wc -l <<<"$help")" -lt 25 ] || fail "render --help is the whole usage"

output=$("$sightline" render levels/x.json --record x.json 2>&1)
[ $? -eq 2 ] || fail "render --record was not refused"
[[ "$output" == "sightline: render does not take --record; \`sightline render --help\` lists what it takes"* ]] ||
  fail "render --record: $output"
output=$("$sightline" info levels/x.json --frames 3 2>&1)
[ $? -eq 2 ] || fail "info --frames was not refused"
output=$("$sightline" render levels/x.json --siz 3x3 2>&1)
[ $? -eq 2 ] || fail "--siz was not refused"
[[ "$output" == 'sightline: unknown option '"'"'--siz'"'"'; did you mean "--size"?'* ]] || fail "--siz: $output"
output=$("$sightline" rendr 2>&1)
[[ "$output" == 'sightline: unknown command '"'"'rendr'"'"'; did you mean "render"?'* ]] || fail "rendr: $output"

# A soft-shadow level renders until the denoiser has settled unless told otherwise, and a single
# frame of it says it is noisy.
penumbra="$(dirname "$0")/../levels/02_penumbra.json"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
output=$("$sightline" render "$penumbra" --size 32x18 --out "$work/a.png" 2>&1) || fail "render: $output"
grep -q "(median after the first)" <<<"$output" || fail "a soft-shadow render took one frame: $output"
grep -q "^note:" <<<"$output" && fail "a settled render printed a note: $output"
output=$("$sightline" render "$penumbra" --size 32x18 --frames 1 --out "$work/b.png" 2>&1) ||
  fail "render --frames 1: $output"
grep -q "^note: 1 frame of a level with soft shadows: the denoiser settles over 32 frames" <<<"$output" ||
  fail "a single noisy frame was not called noisy: $output"

version=$("$sightline" --version) || fail "--version exited with $?"
grep -q "^sightline [0-9]*\.[0-9]*\.[0-9]*$" <<<"$version" || fail "--version: $version"
grep -q "^Vulkan device: " <<<"$version" || fail "--version names no device: $version"
echo "PASS: per-command help, refused options with suggestions, settled soft-shadow renders, --version"

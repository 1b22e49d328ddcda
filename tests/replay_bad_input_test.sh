#!/usr/bin/env bash
# `sightline replay` refuses bad replays before running anything: one message naming the file,
# line and column, and a non-zero exit status.
# Usage: replay_bad_input_test.sh path/to/sightline
set -uo pipefail
sightline=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
expect_refusal() {  # replay text, expected message
  printf '%s\n' "$1" >"$work/bad.json"
  output=$("$sightline" replay "$work/bad.json" 2>&1)
  status=$?
  if [ "$status" -eq 0 ] || [ "$output" != "$2" ]; then
    echo "FAIL: status $status; expected: $2"
    echo "got: $output"
    exit 1
  fi
}
expect_refusal '{"replay": 1, "level": "missing.json", "ticks": 10}' \
  "$work/bad.json:1:24: /level: $work/missing.json: cannot open level file"
expect_refusal '{"replay": 1, "level": "missing.json", "ticks": 10, "input": [{"tick": 12}]}' \
  "$work/bad.json:1:72: /input/0/tick: tick 12 is past the end of the replay (ticks: 10)"
expect_refusal '{"replay": 1, "level": "missing.json", "ticks": 10' \
  "$work/bad.json:2:1: invalid JSON"
# A good replay after a bad one: nothing runs when any file is bad.
printf '{"replay": 1, "level": "missing.json", "ticks": 10}\n' >"$work/bad.json"
output=$("$sightline" replay "$(dirname "$0")/../replays/01_first_light_win.json" "$work/bad.json" 2>&1)
[ $? -ne 0 ] || { echo "FAIL: a set with a bad replay passed"; exit 1; }
case "$output" in *PASS*) echo "FAIL: a replay ran although another was bad"; exit 1 ;; esac
# Several bad replays: every one is reported (not only the first), and nothing runs.
printf '{"replay": 1, "level": "missing.json", "ticks": 10, "input": [{"tick": 12}]}\n' >"$work/bad2.json"
output=$("$sightline" replay "$work/bad.json" "$(dirname "$0")/../replays/01_first_light_win.json" \
  "$work/bad2.json" 2>&1)
status=$?
expected="$work/bad.json:1:24: /level: $work/missing.json: cannot open level file
$work/bad2.json:1:72: /input/0/tick: tick 12 is past the end of the replay (ticks: 10)
2 of 3 replays are malformed; none was run"
if [ "$status" -eq 0 ] || [ "$output" != "$expected" ]; then
  echo "FAIL: status $status; expected: $expected"
  echo "got: $output"
  exit 1
fi
echo "PASS: bad replays are refused with file:line:col messages and nothing runs"

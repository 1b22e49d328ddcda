#!/usr/bin/env bash
# Device loss and exhausted memory end `sightline render` and `sightline replay` with one clear
# message and a non-zero exit status: never a hang, a crash, a sanitizer report or a validation
# message (objects left at exit included). The failures are injected into the real Vulkan call
# path with SIGHTLINE_FAULT=<call>[:<nth>] (render/vulkan_error.hpp, docs/ROBUSTNESS.md).
#
# One case:  fault_injection_test.sh SIGHTLINE LEVEL render|replay CALL:NTH EXPECTED [--in-frame]
#   EXPECTED is text the message must hold; --in-frame (replay) also requires that the run got
#   past its setup into the ticks before the fault (the trace has rows), so the fault hit a frame.
# A sweep:   fault_injection_test.sh --sweep SIGHTLINE LEVEL
#   every call of every fault point, one run each, until a run no longer reaches the nth call.
set -uo pipefail

timeout_seconds=120
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A short replay of LEVEL at a tiny size (its level path is absolute, so it can live in $work).
write_replay() {
  local level
  level=$(realpath "$1")
  printf '{"replay": 1, "level": "%s", "size": [32, 18], "ticks": %s}\n' "$level" "$2" \
    >"$work/short.json"
}

# Runs one command with a fault; sets $status and $output.
run_with_fault() {  # sightline level render|replay fault
  local sightline=$1 level=$2 command=$3 fault=$4
  rm -f "$work/trace.csv"
  if [ "$command" = render ]; then
    output=$(SIGHTLINE_FAULT=$fault timeout "$timeout_seconds" "$sightline" render "$level" \
      --size 32x18 --frames 3 --validate --out "$work/out.png" 2>&1)
  else
    output=$(SIGHTLINE_FAULT=$fault timeout "$timeout_seconds" "$sightline" replay \
      "$work/short.json" --validate --trace "$work/trace.csv" 2>&1)
  fi
  status=$?
}

# Checks the last run ended as it must; prints why not and returns 1.
check_clean_failure() {  # label expected
  local label=$1 expected=$2
  local messages
  messages=$(grep -c '^sightline: ' <<<"$output")
  if [ "$status" -eq 124 ]; then
    echo "FAIL $label: no exit within ${timeout_seconds} s (a hang)"
  elif [ "$status" -eq 0 ] || [ "$status" -gt 128 ]; then
    echo "FAIL $label: exit status $status (expected 1: a clean failure)"
  elif grep -qi 'validation' <<<"$output"; then
    echo "FAIL $label: the validation layer spoke"
  elif grep -q 'Sanitizer\|runtime error' <<<"$output"; then
    echo "FAIL $label: a sanitizer report"
  elif [ "$messages" -ne 1 ]; then
    echo "FAIL $label: $messages lines start with 'sightline: ' (expected exactly one)"
  elif ! grep -qF -- "$expected" <<<"$output"; then
    echo "FAIL $label: the message lacks '$expected'"
  else
    return 0
  fi
  echo "$output" | head -20
  return 1
}

if [ "${1:-}" = "--sweep" ]; then
  sightline=$2
  level=$3
  write_replay "$level" 16
  failures=0
  for command in render replay; do
    for call in vkAllocateMemory vkQueueSubmit vkWaitForFences vkQueueWaitIdle; do
      nth=1
      while :; do
        run_with_fault "$sightline" "$level" "$command" "$call:$nth"
        if [ "$status" -eq 0 ] && ! grep -q 'injected by' <<<"$output"; then
          break  # this run makes fewer than nth such calls
        fi
        check_clean_failure "$command $call:$nth" "$call" || failures=$((failures + 1))
        nth=$((nth + 1))
      done
      echo "$command: $call: $((nth - 1)) calls, each failed in turn"
    done
  done
  [ "$failures" -eq 0 ] && echo "PASS: every injected fault ended cleanly" || echo "FAIL: $failures"
  exit $((failures > 0))
fi

sightline=$1
level=$2
command=$3
fault=$4
expected=$5
in_frame=${6:-}
write_replay "$level" 120
run_with_fault "$sightline" "$level" "$command" "$fault"
check_clean_failure "$command $fault" "$expected" || exit 1
if [ "$in_frame" = "--in-frame" ]; then
  rows=$(($(wc -l <"$work/trace.csv") - 1))
  if [ "$rows" -lt 2 ]; then
    echo "FAIL: the fault hit before the first ticks ($rows trace rows): not during a frame"
    exit 1
  fi
  echo "(the replay ran $((rows - 1)) ticks before the fault)"
fi
echo "PASS: $command with SIGHTLINE_FAULT=$fault ends with: $(grep '^sightline: ' <<<"$output")"

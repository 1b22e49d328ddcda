#!/usr/bin/env bash
# `sightline bench --csv --json` writes the printed table's rows, per-pass GPU medians and the
# Embree reference included, at a tiny size with the validation layer on; and --strafe.
# Usage: bench_output_test.sh path/to/sightline path/to/level.json
set -uo pipefail
sightline=$1
level=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$sightline" bench "$level" --size 32x18 --frames 3 --embree-frames 2 --validate \
  --csv "$work/bench.csv" --json "$work/bench.json" >"$work/out.txt" 2>&1 ||
  fail "bench exited with $?: $(cat "$work/out.txt")"
grep -q "trace" "$work/out.txt" || fail "no per-pass columns in the printed table"

python3 - "$work/bench.csv" "$work/bench.json" "$(basename "$level" .json)" <<'PY' || exit 1
import csv, json, sys
csv_file, json_file, level = sys.argv[1:4]
rows = list(csv.DictReader(open(csv_file)))
assert len(rows) == 1, f"expected one CSV row, got {len(rows)}"
row = rows[0]
assert row["level"] == level and row["width"] == "32" and row["height"] == "18", row
assert row["frames"] == "3" and row["embree_frames"] == "2", row
for column in ("median_ms", "trace_ms", "tonemap_ms", "readback_ms", "level_switch_ms",
               "embree_mrays_per_s", "trace_over_embree"):
    assert float(row[column]) > 0, f"{column} = {row[column]}"
assert float(row["denoise_ms"]) >= 0
# Hard shadows only: Embree shoots as many rays as the ray-gen shader counts.
assert row["rays_per_frame"] == row["embree_rays_per_frame"], row
document = json.load(open(json_file))
assert document["embree_threads"] == 2
assert document["camera"] == "still" and document["upscaled_to"] is None, document
entry = document["rows"][0]
assert set(entry["gpu_pass_median_ms"]) == {"trace", "denoise", "tonemap", "readback"}
assert abs(entry["median_ms"] - float(row["median_ms"])) <= 1e-3 * entry["median_ms"]
assert entry["embree"]["rays_per_frame"] == int(row["rays_per_frame"])
PY

# --strafe moves the camera every frame (the denoiser's and upscaler's moving paths), says so,
# leaves the validation layer silent, and the JSON records it and the upscaling.
"$sightline" bench "$level" --size 32x18 --frames 3 --embree-frames 0 --strafe --validate \
  --upscale 64x36 --json "$work/strafe.json" >"$work/strafe.txt" 2>&1 ||
  fail "bench --strafe exited with $?: $(cat "$work/strafe.txt")"
grep -q "the camera strafes 1 cm a frame" "$work/strafe.txt" ||
  fail "bench --strafe did not say the camera strafes: $(cat "$work/strafe.txt")"
python3 - "$work/strafe.json" <<'PY' || exit 1
import json, sys
document = json.load(open(sys.argv[1]))
assert document["camera"] == "strafing", document
assert document["upscaled_to"] == {"width": 64, "height": 36}, document
PY

# Bad input names the option and what it expected.
output=$("$sightline" bench "$level" --embree-frames many 2>&1)
[ $? -eq 2 ] || fail "--embree-frames many was accepted"
case "$output" in
  *"--embree-frames: expected a whole number from 0 to 1000000, got 'many'"*) ;;
  *) fail "unexpected message: $output" ;;
esac
echo "PASS: bench writes its table as CSV and JSON"

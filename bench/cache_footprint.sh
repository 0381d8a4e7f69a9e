#!/usr/bin/env bash
# The footprint benchmark: what one radiating body leaves in the cache, how long the radiation
# takes from an empty cache and from a filled one, and how fast an oversized run is refused.
#   1. The refusal: `simulate models/cases/plate_rough_80kmh.toml` with the direct history engine
#      on the default grid (0.1 s, about 78 GB of kernel), radiation off, REPEAT times; prints
#      each run's exit status and wall time (it must be 2, well within a second).
#   2. The case (default plate_rough_80kmh, 0.2 s) cold into an empty cache in a temporary folder,
#      then warm into the same folder; prints the entries' count, total and largest size, and
#      each run's radiation time (summary.json radiation.time_s).
# Run it once with BIN pointing at the build before a change and once at the build after it to
# compare (each from its own empty cache).
#
# Usage: bench/cache_footprint.sh [CASE.toml [KEY=VALUE ...]]
#   BIN=PATH     the rollnoise to run (default: build/, as built by tools/setup.sh)
#   REPEAT=N     runs of the refusal (default 5)
set -euo pipefail
cd "$(dirname "$0")/.."
case_file=${1:-models/cases/plate_rough_80kmh.toml}
shift || true
sets=()
for kv in "$@"; do sets+=(--set "$kv"); done
bin=${BIN:-$PWD/build/tools/rollnoise/rollnoise}
work=$(mktemp -d "${TMPDIR:-/tmp}/rollnoise-bench-footprint.XXXXXX")
trap 'rm -rf "$work"' EXIT

echo "refusal of the direct engine on the default grid (0.1 s, radiation off):"
for ((i = 1; i <= ${REPEAT:-5}; i++)); do
  start=$(date +%s.%N)
  status=0
  "$bin" simulate models/cases/plate_rough_80kmh.toml --out "$work/direct" --set rolling.duration=0.1 \
    --set rolling.history=direct --set radiation.enabled=false 2>"$work/refusal.txt" || status=$?
  end=$(date +%s.%N)
  awk -v s="$start" -v e="$end" -v st="$status" 'BEGIN { printf "  exit status %d in %.3f s\n", st, e - s }'
done
echo "  message: $(cat "$work/refusal.txt")"

radiation_time() {
  /usr/bin/python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))["radiation"]; print("%.2f s, %d of %d anchors from the cache" % (r["time_s"], r["anchors_from_cache"], r["anchors"]))' "$1/summary.json"
}
for run in cold warm; do
  "$bin" simulate "$case_file" --out "$work/$run" --cache "$work/cache" --set output.plots=false "${sets[@]}" >/dev/null
  echo "$run: radiation $(radiation_time "$work/$run")"
done
find "$work/cache" -name 'radiation-*.h5' -printf '%s\n' | sort -n | awk '
  { total += $1; n++; if (n == 1) smallest = $1; largest = $1 }
  END { printf "entries of one radiating body: %d, %.1f MB in all, %.2f MB to %.2f MB each\n", n, total / 1e6, smallest / 1e6, largest / 1e6 }'

#!/usr/bin/env bash
# Two builds of the program side by side on the rolling tyre: 1 s of rolling of CASE (default
# plate_rough_80kmh, radiation off, modal engine) with BEFORE and AFTER, interleaved REPEAT times
# (default 3), each timed by its fastest run (on a shared machine the fastest is the least
# disturbed). Prints the contact stage, the step loop, the contact problem (LCP) and the history
# engine of each, with the LCP's iteration counts, and the ratios. Timed CLI runs; the figures
# come from each run's summary.json.
#   bash bench/tyre_speed_compare.sh BEFORE_EXE AFTER_EXE [CASE [KEY=VALUE ...]]
# KEY=VALUE pairs are passed on as --set (e.g. rolling.band_top=0 for the 512-cell grid).
# Keep a copy of the old program before rebuilding, e.g. cp build/tools/rollnoise/rollnoise /tmp/before.
set -euo pipefail
cd "$(dirname "$0")/.."
(($# >= 2)) || { echo "usage: bash bench/tyre_speed_compare.sh BEFORE_EXE AFTER_EXE [CASE [KEY=VALUE ...]]" >&2; exit 2; }
before=$1
after=$2
case=${3:-models/cases/plate_rough_80kmh.toml}
overrides=()
for pair in "${@:4}"; do overrides+=(--set "$pair"); done
repeat=${REPEAT:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export ROLLNOISE_CACHE="$out/cache"
run() {  # exe folder
  CI=true "$1" simulate "$case" --out "$out/$2" --set rolling.duration=1.0 --set radiation.enabled=false \
    --set output.plots=false --set output.wav=false "${overrides[@]}" >/dev/null
}
run "$before" warmup  # fills the cache, so that neither side pays for it
for ((i = 1; i <= repeat; ++i)); do
  run "$before" "before$i"
  run "$after" "after$i"
done
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$out" "$repeat" "$(basename "$case" .toml)" <<'EOF'
import json, sys
out, repeat, name = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def fastest(side):
    runs = [json.load(open(f"{out}/{side}{i}/summary.json")) for i in range(1, repeat + 1)]
    return min(runs, key=lambda d: d["contact_time_s"]), sorted(d["contact_time_s"] for d in runs)
b, b_all = fastest("before")
a, a_all = fastest("after")
print(f"{name}, 1 s of rolling: {b['grid']['contact_points']} contact points, {b['settings']['steps']} steps; "
      f"fastest of {repeat} interleaved runs each")
for label, d, every in (("before", b, b_all), ("after", a, a_all)):
    print(f"  {label}: contact stage {d['contact_time_s']:.2f} s (all: {', '.join(f'{t:.2f}' for t in every)}), "
          f"step loop {d['step_loop_time_s']:.2f} s, contact problem {d['lcp_time_s']:.2f} s, "
          f"history engine {d['history_engine_time_s']:.2f} s; {d['lcp_cg_iterations']} conjugate-gradient and "
          f"{d['lcp_iterations']['total']} pivoting iterations")
print(f"  after/before: contact stage {a['contact_time_s'] / b['contact_time_s']:.2f}, "
      f"contact problem {a['lcp_time_s'] / b['lcp_time_s']:.2f}")
EOF

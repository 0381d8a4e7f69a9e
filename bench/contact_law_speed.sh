#!/usr/bin/env bash
# Speed of the texture contact law ([rolling] contact_law = "texture"): 1 s of rolling of CASE
# (default plate_rough_80kmh: 22 m of dac11 under 20 lateral lines) with the rigid cells and with
# the laws, side by side in one run of this script: the laws computed from an empty cache, then
# read from it, and the step loop per step of each. Radiation off. Timed CLI runs; the figures
# come from each run's summary.json.
#   bash bench/contact_law_speed.sh [CASE [DURATION_S]]
# ROLLNOISE_EXE picks the binary (default: the Release build without assertions, build-bench/);
# REPEAT=N runs the rigid and the warm texture case N times, interleaved, and times each by its
# fastest run (on a shared machine the fastest is the least disturbed);
# CALLGRIND=1 adds the instruction counts of the contact step (several minutes under valgrind).
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/bench_binary.sh
case=${1:-models/cases/plate_rough_80kmh.toml}
duration=${2:-1.0}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export ROLLNOISE_CACHE="$out/cache"  # empty: the first texture run computes the laws
run() {  # name law
  CI=true "$exe" simulate "$case" --out "$out/$1" --set rolling.duration="$duration" --set radiation.enabled=false \
    --set output.plots=false --set "rolling.contact_law=\"$2\"" >/dev/null
}
field() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d$2)" "$out/$1/summary.json"; }
repeat=${REPEAT:-1}
run texture_cold texture
for ((i = 1; i <= repeat; ++i)); do
  run "rigid$i" rigid
  run "texture_warm$i" texture
done
# The fastest of the repeated runs as rigid/ and texture_warm/.
fastest() {  # name -> the run's folder with the smallest step loop
  python3 -c "import json,sys; print(min(sys.argv[2:], key=lambda d: json.load(open(d+'/summary.json'))['step_loop_time_s']))" \
    "$1" "$out/$1"[0-9]*
}
ln -s "$(fastest rigid)" "$out/rigid"
ln -s "$(fastest texture_warm)" "$out/texture_warm"
steps=$(field rigid "['settings']['steps']")
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "$(basename "$case" .toml), ${duration} s: $steps steps, $(field texture_cold "['texture_contact_law']['cells']") cells of $(field texture_cold "['texture_contact_law']['pixels_along']") x $(field texture_cold "['texture_contact_law']['pixels_across']") pixels"
echo "laws: computed in $(field texture_cold "['texture_contact_law']['seconds']") s (empty cache), read in $(field texture_warm "['texture_contact_law']['seconds']") s (from cache: $(field texture_warm "['texture_contact_law']['from_cache']"))"
rigid_loop=$(field rigid "['step_loop_time_s']")
law_loop=$(field texture_warm "['step_loop_time_s']")
echo "step loop (fastest of $repeat): rigid cells ${rigid_loop} s, texture laws ${law_loop} s: $(python3 -c "print(round($law_loop/$rigid_loop, 2))")x; per step $(python3 -c "print(round(1e3*$rigid_loop/$steps, 3))") ms and $(python3 -c "print(round(1e3*$law_loop/$steps, 3))") ms"
echo "contact stage: rigid $(field rigid "['contact_time_s']") s, texture cold $(field texture_cold "['contact_time_s']") s, warm $(field texture_warm "['contact_time_s']") s"
# Instruction counts of the contact step alone (load-independent), under callgrind (CALLGRIND=1): the rigid cells' LCP (PMatrixLcpSolver::solve) against the laws' Newton step
# (TreadNewtonContact::solve), each as the difference of a 0.015 s and a 0.005 s run, which
# leaves out the steady state's solves.
if [[ ${CALLGRIND:-0} == 1 ]] && command -v valgrind >/dev/null; then
  count() {  # law duration function -> instructions inside function
    CI=true valgrind --tool=callgrind --callgrind-out-file="$out/cg.$1.$2" --toggle-collect="$3" "$exe" simulate "$case" \
      --out "$out/cg_$1_$2" --set rolling.duration="$2" --set radiation.enabled=false --set output.plots=false \
      --set "rolling.contact_law=\"$1\"" >/dev/null 2>&1
    callgrind_annotate "$out/cg.$1.$2" 2>/dev/null | awk '/PROGRAM TOTALS/ { gsub(/,/, "", $1); print $1; exit }'
  }
  steps_of() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['settings']['steps'])" "$out/cg_$1_$2/summary.json"; }
  rigid_a=$(count rigid 0.005 'rollnoise::PMatrixLcpSolver::solve*'); rigid_b=$(count rigid 0.015 'rollnoise::PMatrixLcpSolver::solve*')
  law_a=$(count texture 0.005 'rollnoise::TreadNewtonContact::solve*'); law_b=$(count texture 0.015 'rollnoise::TreadNewtonContact::solve*')
  d=$(( $(steps_of rigid 0.015) - $(steps_of rigid 0.005) ))
  echo "contact step, instructions per step (callgrind): rigid $(( (rigid_b - rigid_a) / d )), texture laws $(( (law_b - law_a) / d )): $(python3 -c "print(round(($law_b - $law_a)/($rigid_b - $rigid_a), 2))")x"
fi

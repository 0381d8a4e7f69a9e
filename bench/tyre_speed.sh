#!/usr/bin/env bash
# Speed of the rolling tyre: 1 s of rolling with the modal engine, and a shortened run with both
# engines for the per-step speed-up over `direct` (whose dense kernel grows with the run: it is
# the reference, not a production engine). Timed CLI runs; the figures come from each run's
# summary.json (step_loop_time_s: the time-step loop alone).
#   bash bench/tyre_speed.sh [CASE [SHORT_DURATION_S [KEY=VALUE ...]]]
# KEY=VALUE pairs are passed on as --set (e.g. rolling.band_top=0 for the 512-cell grid).
# Defaults: models/cases/plate_rough_80kmh.toml, 0.07 s. For two_layer_rough_80kmh.toml give a
# shorter run (0.005 s): the direct kernel takes P² doubles per lag (33 MB at 2040 points).
# A two-layer case also reports the time to build its tables (an empty cache) and to load them
# from the cache (rerun).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh >/dev/null
cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DROLLNOISE_ASSERTIONS=OFF -DROLLNOISE_BUILD_TESTS=OFF -DROLLNOISE_PYTHON=OFF >/dev/null
cmake --build build-bench -j "$(nproc)" --target rollnoise >/dev/null
exe=build-bench/tools/rollnoise/rollnoise
case=${1:-models/cases/plate_rough_80kmh.toml}
short=${2:-0.07}
overrides=()
for pair in "${@:3}"; do overrides+=(--set "$pair"); done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export ROLLNOISE_CACHE="$out/cache"  # an empty cache: the first run builds the tables
run() {  # name engine duration
  CI=true "$exe" simulate "$case" --out "$out/$1" --set rolling.history="$2" --set rolling.duration="$3" \
    --set output.plots=false "${overrides[@]}" >/dev/null
}
field() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d$2)" "$out/$1/summary.json"; }
run modal_1s modal 1.0
run modal_short modal "$short"
run direct_short direct "$short"
steps_short=$(field modal_short "['settings']['steps']")
modal_step=$(python3 -c "print($(field modal_short "['step_loop_time_s']")/($steps_short+1))")
direct_step=$(python3 -c "print($(field direct_short "['step_loop_time_s']")/($steps_short+1))")
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
if grep -q '"mode_fit"' "$out/modal_1s/summary.json"; then
  echo "tables (empty cache, first run): tabulation $(field modal_1s "['mode_fit']['table_time_s']") s, pole fits $(field modal_1s "['mode_fit']['fit_time_s']") s ($(field modal_1s "['mode_fit']['modes']") modes, $(field modal_1s "['mode_fit']['poles']") poles)"
  echo "tables from the cache (next runs): $(field modal_short "['mode_fit']['table_time_s']") s + $(field modal_short "['mode_fit']['fit_time_s']") s (from cache: $(field modal_short "['mode_fit']['table_from_cache']"), $(field modal_short "['mode_fit']['fits_from_cache']"))"
fi
echo "$(basename "$case" .toml), $(field modal_1s "['grid']['contact_points']") contact points, $(field modal_1s "['settings']['steps']") steps per simulated second"
echo "modal, 1 s of rolling: step loop $(field modal_1s "['step_loop_time_s']") s, contact stage $(field modal_1s "['contact_time_s']") s, whole run with outputs $(field modal_1s "['wall_time_s']") s"
loop_1s=$(field modal_1s "['step_loop_time_s']")
echo "  of the step loop: contact problem (LCP) $(field modal_1s "['lcp_time_s']") s ($(python3 -c "print(round(100*$(field modal_1s "['lcp_time_s']")/$loop_1s))") %), history engine $(field modal_1s "['history_engine_time_s']") s ($(python3 -c "print(round(100*$(field modal_1s "['history_engine_time_s']")/$loop_1s))") %); $(python3 -c "print(round(1e3*$loop_1s/$(field modal_1s "['settings']['steps']"), 2))") ms per step"
modal_history=$(python3 -c "print($(field modal_short "['history_engine_time_s']")/($steps_short+1))")
direct_history=$(python3 -c "print($(field direct_short "['history_engine_time_s']")/($steps_short+1))")
steps_1s=$(field modal_1s "['settings']['steps']")
echo "shortened run ($((steps_short + 1)) steps), per step: whole step modal ${modal_step} s, direct ${direct_step} s: speed-up $(python3 -c "print(round($direct_step/$modal_step, 1))")x"
echo "  history engine alone: modal ${modal_history} s, direct ${direct_history} s (mean over a history of 0-${steps_short} steps): speed-up $(python3 -c "print(round($direct_history/$modal_history, 1))")x"
# The direct engine's history cost grows linearly with the step (eq. 3): over 0…N its last step
# costs twice its mean. Whole step at the end of the shortened run, both engines:
echo "  whole step at the end of the shortened run: direct $(python3 -c "print(round($direct_step+$direct_history, 4))") s (its history cost doubled from the mean), modal ${modal_step} s: speed-up $(python3 -c "print(round(($direct_step+$direct_history)/$modal_step, 1))")x"
# The direct engine's cost is linear in the history length (eq. 3): extrapolate to the last
# step of 1 s of rolling, where its kernel would need $steps_1s lags (P² doubles each).
# Per simulated second: the direct history's cost grows linearly with the step, so over the
# steps of 1 s it sums to about half its last step's cost times the steps (the whole step adds
# the same contact solve as the modal run's).
echo "  per simulated second: modal (measured) ${loop_1s} s; direct (history extrapolated from the shortened run, plus the modal run's contact solve) $(python3 -c "print(round($direct_history*$steps_1s/$steps_short*$steps_1s + $loop_1s - $(field modal_1s "['history_engine_time_s']")))") s: $(python3 -c "print(round(($direct_history*$steps_1s/$steps_short*$steps_1s + $loop_1s - $(field modal_1s "['history_engine_time_s']"))/$loop_1s))")x"
echo "  direct at the end of 1 s (history ${steps_1s} steps, extrapolated linearly): $(python3 -c "print(round($direct_history*2*$steps_1s/$steps_short, 2))") s per step, $(python3 -c "print(round($direct_history*2*$steps_1s/$steps_short/$modal_history))")x the modal engine; its kernel alone would take $(python3 -c "print(round($steps_1s*$(field modal_1s "['grid']['contact_points']")**2*8/1e9, 1))") GB"

#!/usr/bin/env bash
# Scaling of `rollnoise study` from 1 to 2 threads and from 1 to 2 MPI ranks (issue 12), on the
# 2 x 2 study of the tests (tests/cli/test_study_cli.cpp: the plate tyre on dac11 and sma11 at 80
# and 110 km/h, a coarse grid, no WAV or plots), without the radiation cache so that every run
# does the same work. Each configuration runs REPEATS times from scratch (--restart); the
# median wall time is printed with the load average before each run. Usage:
#   bench/study_scaling.sh [DURATION_S] [REPEATS]     (default 0.01 s of rolling a case, 3)
set -euo pipefail
cd "$(dirname "$0")/.."
duration=${1:-0.01}
repeats=${2:-3}
bin=$PWD/build/tools/rollnoise/rollnoise
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
models=$PWD/models
cat > "$work/base.toml" <<TOML
[tyre]
file = "$models/tyres/passenger_205_55R16.toml"
[road]
type = "flat"
[rolling]
speed = 22.222
duration = 0.01
static_load = 3200.0
points_lateral = 6
contact_window = 0.15
band_top = 1000
[radiation]
receivers = ["cpx_front", "cpx_rear"]
mesh_around = 32
mesh_across = 2
sidewall_rings = 4
anchor_spacing = 500
contact_refinement = 3
[output]
plots = false
wav = false
TOML
cat > "$work/study.toml" <<TOML
[study]
name = "two_by_two"
case = "base.toml"
[set]
rolling.duration = $duration
[vary]
road.surface = ["$models/surfaces/dac11.toml", "$models/surfaces/sma11.toml"]
rolling.speed = [22.222, 30.556]
TOML
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "machine: $(nproc) cores; 2 x 2 study, $duration s of rolling a case, no cache, $repeats runs each"
run() {  # label, command...
  local label=$1; shift
  local times=() loads=()
  for ((i = 0; i < repeats; ++i)); do
    loads+=("$(cut -d' ' -f1 /proc/loadavg)")
    local s e
    s=$(date +%s.%N)
    (cd "$work" && "$@" >/dev/null 2>&1)
    e=$(date +%s.%N)
    times+=("$(echo "$e - $s" | bc)")
  done
  local median
  median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(((repeats + 1) / 2))p")
  printf '%-22s median %6.2f s   runs: %s   load before each: %s\n' "$label" "$median" "${times[*]}" "${loads[*]}"
}
run "--threads 1" "$bin" study study.toml --out s --restart --no-cache --threads 1
run "--threads 2" "$bin" study study.toml --out s --restart --no-cache --threads 2
if command -v mpirun >/dev/null; then
  run "mpirun -n 1" mpirun -n 1 --oversubscribe "$bin" study study.toml --out s --restart --no-cache
  run "mpirun -n 2" mpirun -n 2 --oversubscribe "$bin" study study.toml --out s --restart --no-cache
  run "mpirun -n 2 --threads 2" mpirun -n 2 --oversubscribe "$bin" study study.toml --out s --restart --no-cache --threads 2
fi

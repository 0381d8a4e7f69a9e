#!/usr/bin/env bash
# The main job: set up, build, and run the demo cases in out/demo/: the paper's §4 validation
# cases (an SDOF and two coupled SDOFs on a sine and a random road) with their figures, and the
# 205/55 R16 tyre rolling on a smooth road, a dense asphalt concrete (models/surfaces/dac11)
# and over a cleat, and as the seed's two-layer tyre on the smooth road. The dense-asphalt and cleat runs radiate to the CPX and SPB microphones:
# spectrum.csv, LAeq in summary.json, <receiver>.wav (and spb_passby.wav), spectrum.png and the
# energy budget (budget.csv).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh rollnoise   # the program only: the tests are built by tools/test.sh

out=out/demo
mkdir -p "$out"

# Calibration: the tyre model fitted to the synthetic example mobilities in
# data/mobility, giving a model file any tyre case can roll with (--set tyre.file=...). It runs
# beside the cases below, whose contact loops leave one of two cores idle; its messages follow
# theirs.
calibration_log=$(mktemp)
build/tools/rollnoise/rollnoise calibrate models/tyres/passenger_205_55R16.toml \
  --data data/mobility/tyre_point_mobility.csv data/mobility/tyre_transfer_mobility.csv \
  --out "$out/calibrated_tyre" >"$calibration_log" 2>&1 &
calibration=$!
trap 'kill "$calibration" 2>/dev/null || true; rm -f "$calibration_log"' EXIT

# The runs of docs/getting-started.md's table, named: a glob would take every case added later.
for case in models/cases/larsson2000_*.toml models/cases/plate_rough_80kmh.toml models/cases/plate_cleat_50kmh.toml \
    models/cases/plate_smooth_80kmh.toml; do
  name=$(basename "$case" .toml)
  build/tools/rollnoise/rollnoise simulate "$case" --out "$out/$name"
done
# The seed's two-layer tyre on the smooth road: the first run tabulates its modes and
# fits poles to them (about 16 s on 2 cores; cached for the next runs).
build/tools/rollnoise/rollnoise simulate models/cases/two_layer_smooth_80kmh.toml --out "$out/two_layer_smooth_80kmh"

# Road surfaces: the dense asphalt the rough case rolls on, and a measured chip-seal
# laser profile, each analysed as a road engineer would (MPD, texture spectrum).
build/tools/rollnoise/rollnoise road models/surfaces/dac11.toml --out "$out/road_dac11"
build/tools/rollnoise/rollnoise road data/surfaces/captif/20211011_aylesbury_dec_station_0.dat --out "$out/road_captif"

if ! wait "$calibration"; then
  cat "$calibration_log" >&2
  exit 1
fi
cat "$calibration_log"

# The paper's Fig. 3, 4a and 4b, drawn from the runs' CSV files; each script stays beside
# its PNG so it can be restyled and redrawn.
mkdir -p "$out/figures"
for script in docs/figures/fig*.gp; do
  cp "$script" "$out/figures/"
  (cd "$out/figures" && gnuplot "$(basename "$script")")
done
echo "demo: results in $out/ (one folder per case; paper figures in $out/figures/;"
echo "      listen to $out/plate_rough_80kmh/cpx_front.wav and spb_passby.wav)"

#!/usr/bin/env bash
# The CPX level against speed: the rough-road tyre case at 50, 80 and 100 km/h, its
# LAeq at the CPX microphones, and the slope in dB per decade of speed, fitted by gnuplot.
# Writes out/speed_study/{speed_study.csv, speed_study.gp, speed_study.png} and one run folder
# per speed. Needs a built tree (bash tools/setup.sh).
#
# Every speed now carries the bands up to 5 kHz (sub-steps per cell). The levels
# are also given over the bands up to 1.6 kHz: above about 0.5·V/Δx (1.8 kHz at 50 km/h, with
# Δx the 3.9 mm grid spacing around the tyre) the bands carry the cell-passing artefact of the
# fixed contact points (docs/physics/contact.md, "The band up to 5 kHz"), so those are the bands all three speeds
# give cleanly.
set -euo pipefail
cd "$(dirname "$0")/.."
rollnoise=build/tools/rollnoise/rollnoise
out=out/speed_study
mkdir -p "$out"
case=models/cases/plate_rough_80kmh.toml
echo "speed_kmh,cpx_front_LAeq_dB,cpx_rear_LAeq_dB,cpx_front_LAeq_to_1600Hz_dB,cpx_rear_LAeq_to_1600Hz_dB,spb_LAeq_dB,spb_passby_LAFmax_dB,LwA_dB" > "$out/speed_study.csv.tmp"
for kmh in 50 80 100; do
  speed=$(awk -v k="$kmh" 'BEGIN { printf "%.6f", k / 3.6 }')
  "$rollnoise" simulate "$case" --out "$out/${kmh}kmh" --set "rolling.speed=$speed"
  summary="$out/${kmh}kmh/summary.json"
  # The value of "KEY" inside the block of "BLOCK" in summary.json (printed by rollnoise, two
  # spaces per level, one key per line).
  value() { awk -v block="\"$1\": {" -v key="\"$2\":" '
      index($0, block) { inside = 1; next }
      inside && index($0, key) { gsub(/[,]/, "", $2); print $2; exit }
      inside && /^ *}/ { inside = 0 }' "$summary"; }
  # 10 lg Σ 10^(LpA/10) over a receiver's bands up to 1.6 kHz in spectrum.csv.
  band_limited() { awk -F, -v r="$1" '$1 == r && $2 + 0 <= 1600 { s += 10 ^ ($4 / 10) } END { printf "%.3f", 10 * log(s) / log(10) }' \
      "$out/${kmh}kmh/spectrum.csv"; }
  echo "$kmh,$(value cpx_front LAeq_dB),$(value cpx_rear LAeq_dB),$(band_limited cpx_front),$(band_limited cpx_rear),$(value spb LAeq_dB),$(value spb_passby LAFmax_dB),$(value sound_power LwA_dB)" \
      >> "$out/speed_study.csv.tmp"
done
mv "$out/speed_study.csv.tmp" "$out/speed_study.csv"

cat > "$out/speed_study.gp" <<'GP'
# Drawn by tools/speed_study.sh from speed_study.csv; run `gnuplot speed_study.gp` to redraw.
set terminal pngcairo size 900,550 noenhanced font 'DejaVu Sans,10'
set output 'speed_study.png'
set datafile separator ','
set grid
set logscale x
set xrange [40:125]
set xtics (50, 63, 80, 100, 125)
set xlabel 'speed (km/h)'
set ylabel 'LAeq at the CPX microphones (dB(A))'
set key bottom right
# L = A + B lg(V): B is the slope in dB per decade of speed.
f(x) = a + b * log10(x)
fit f(x) 'speed_study.csv' skip 1 using 1:(($4 + $5) / 2) via a, b
set title sprintf('CPX level against speed, 205/55 R16 on the rough road: %.1f dB per decade (bands to 1.6 kHz)', b)
plot 'speed_study.csv' skip 1 using 1:2 with linespoints pt 7 title 'cpx_front, whole band', \
     '' skip 1 using 1:3 with linespoints pt 7 title 'cpx_rear, whole band', \
     '' skip 1 using 1:(($4 + $5) / 2) with points pt 5 ps 1.2 title 'CPX mean, bands to 1.6 kHz', \
     f(x) with lines dt 2 title 'fit A + B lg V'
GP
(cd "$out" && gnuplot speed_study.gp 2> fit.log || { cat fit.log >&2; exit 1; })
cat "$out/speed_study.csv"
grep -E "^b +=" "$out/fit.log" | tail -1

#!/usr/bin/env bash
# The surface library at a glance: runs `rollnoise road` on every surface of
# models/surfaces/ and on the measured CAPTIF profiles (the chip seal's two longitudinal records and
# the fine asphalt's nine transverse lines), and writes
# out/surface_library/{library.csv, texture_spectra.csv, texture_spectra.gp, texture_spectra.png}:
# MPD, skewness (per line, detrended) and the texture levels at 5, 10, 20, 40 and 80 mm per
# surface, and all spectra in one
# figure. Needs a built tree (bash tools/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
rollnoise=build/tools/rollnoise/rollnoise
out=out/surface_library
mkdir -p "$out"
surfaces=(dac11 sma11 sma8 pa16 pa2l thin6 chipseal iso10844 eacc tined captif_fine)
for s in "${surfaces[@]}"; do
  "$rollnoise" road "models/surfaces/$s.toml" --out "$out/$s"
done
for station in 0 1; do
  "$rollnoise" road "data/surfaces/captif/20211011_aylesbury_dec_station_$station.dat" --out "$out/captif_$station"
done
# The measured fine dense asphalt (nine 200 mm transverse lines: bands up to 12.5 mm).
"$rollnoise" road data/surfaces/captif-transverse/20231114_cpx_demo.csv --out "$out/captif_transverse"
# texture.csv of each into one long table, and the library table.
echo "surface,wavelength_m,Ltx_dB" > "$out/texture_spectra.csv.tmp"
echo "surface,mpd_mm,skewness,Ltx_5mm_dB,Ltx_10mm_dB,Ltx_20mm_dB,Ltx_40mm_dB,Ltx_80mm_dB" > "$out/library.csv.tmp"
for name in "${surfaces[@]}" captif_0 captif_1 captif_transverse; do
  awk -F, -v s="$name" 'NR > 1 { print s "," $1 "," $2 }' "$out/$name/texture.csv" >> "$out/texture_spectra.csv.tmp"
  mpd=$(awk -F': ' '/^  "mpd_m"/ { gsub(/,/, "", $2); printf "%.2f", $2 * 1000 }' "$out/$name/summary.json")
  skewness=$(awk -F': ' '/^  "skewness"/ { gsub(/,/, "", $2); printf "%+.2f", $2 }' "$out/$name/summary.json")
  level() { awk -F, -v w="$1" 'NR > 1 && ($1 - w) ^ 2 < 1e-12 { printf "%.1f", $2 }' "$out/$name/texture.csv"; }
  echo "$name,$mpd,$skewness,$(level 0.005),$(level 0.01),$(level 0.02),$(level 0.04),$(level 0.08)" >> "$out/library.csv.tmp"
done
mv "$out/texture_spectra.csv.tmp" "$out/texture_spectra.csv"
mv "$out/library.csv.tmp" "$out/library.csv"
cat > "$out/texture_spectra.gp" <<'GP'
# Drawn by tools/surface_library.sh from texture_spectra.csv; run `gnuplot texture_spectra.gp` to redraw.
set terminal pngcairo size 1000,600 noenhanced font 'DejaVu Sans,10'
set output 'texture_spectra.png'
set datafile separator ','
set grid
set logscale x
set xrange [2:200]
set yrange [10:70]
set title 'Texture level spectra of the surface library (ISO 13473-4, analysed by rollnoise road)'
set xlabel 'texture wavelength (mm)'
set ylabel 'L_tx (dB re 1 um)'
set key outside right
surfaces = 'dac11 sma11 sma8 pa16 pa2l thin6 chipseal iso10844 eacc tined captif_fine'
measured = 'captif_0 captif_1 captif_transverse'
plot for [s in surfaces] 'texture_spectra.csv' using (strcol(1) eq s ? $2*1000 : 1/0):3 \
       with linespoints pt 7 ps 0.6 title s, \
     for [s in measured] 'texture_spectra.csv' using (strcol(1) eq s ? $2*1000 : 1/0):3 \
       with lines dt 2 lw 2 title s.' (measured)'
GP
(cd "$out" && gnuplot texture_spectra.gp)
column -s, -t "$out/library.csv"

#!/usr/bin/env bash
# Validation against published measurements: reruns the computed side of the table
# in docs/validation.md. The 205/55 R16 tyre case (models/cases/plate_rough_80kmh.toml, 0.2 s)
# rolls on each library surface at 50 and 80 km/h; the CPX level is the energy mean of the two
# CPX microphones (cpx_front, cpx_rear), as ISO 11819-2 averages its microphones.
# Writes out/validation/{validation.csv, spectra.csv, validation_table.md}, the figure of the CPX
# spectra per surface at 80 km/h (cpx_spectra_surfaces.{gp,png}, the front page's figure) and one run folder per
# surface and speed (a finished run is kept: delete its folder, or pass --force, to redo it).
# Needs a built tree (bash tools/setup.sh). Takes 1.5-2 min per run on 2 cores.
#
# Another tyre or contact: VALIDATION_CASE (a case file, default the plate's), VALIDATION_SET
# ("rolling.contact_law=\"texture\" ...": --set for every run) and VALIDATION_OUT (the folder,
# default out/validation), e.g.
#   VALIDATION_CASE=models/cases/two_layer_rough_80kmh.toml VALIDATION_OUT=out/validation_two_layer \
#     bash tools/validation.sh
#
# The measured values are those of docs/cpx_measurements.md, with their sources:
#   [C1] Krivanek, Pavkova & Jedlicka (CDV), CPX at 50 km/h: SMA 11S 92.8, ACO 11S 89.8 dB(A)
#   [C2] Flemish AWV CPX surveys (SRTT), 80 km/h: SMA-C 10 mm 99.6 (mean of 70), EACC 0/6.3 98.5
set -euo pipefail
cd "$(dirname "$0")/.."
rollnoise=${ROLLNOISE:-build/tools/rollnoise/rollnoise}
out=${VALIDATION_OUT:-out/validation}
force=0
[[ "${1:-}" == "--force" ]] && force=1
mkdir -p "$out"
case=${VALIDATION_CASE:-models/cases/plate_rough_80kmh.toml}
extra=()
read -r -a settings <<< "${VALIDATION_SET:-}"
for s in "${settings[@]}"; do extra+=(--set "$s"); done
# VALIDATION_SURFACES="dac11 sma11 ..." runs a subset at 80 km/h, VALIDATION_SURFACES_50 at 50 km/h.
read -r -a surfaces <<< "${VALIDATION_SURFACES:-dac11 sma11 sma8 pa16 pa2l thin6 chipseal iso10844 eacc tined captif_fine}"
read -r -a surfaces_50 <<< "${VALIDATION_SURFACES_50:-dac11 sma11 pa16 pa2l captif_fine}"

run() {  # surface speed_kmh
  local dir="$out/$1_$2kmh"
  if [[ $force -eq 1 || ! -f "$dir/summary.json" ]]; then
    local speed
    speed=$(awk -v k="$2" 'BEGIN { printf "%.6f", k / 3.6 }')
    "$rollnoise" simulate "$case" --out "$dir" --set "road.surface=models/surfaces/$1.toml" --set "rolling.speed=$speed" \
      "${extra[@]}"
  fi
}
for s in "${surfaces[@]}"; do run "$s" 80; done
for s in "${surfaces_50[@]}"; do run "$s" 50; done

# CPX level: 10 lg of the mean of 10^(LAeq/10) over cpx_front and cpx_rear (summary.json).
cpx() {
  awk '/"cpx_front": \{|"cpx_rear": \{/ { inside = 1 } inside && /"LAeq_dB"/ { gsub(/,/, "", $2); s += 10 ^ ($2 / 10); n++; inside = 0 }
       END { printf "%.1f", 10 * log(s / n) / log(10) }' "$1/summary.json"
}
# A-weighted CPX spectrum (energy mean of the microphones per band) in long form.
echo "surface,speed_kmh,band_hz,LpA_dB" > "$out/spectra.csv.tmp"
for dir in "$out"/*_*kmh; do
  name=$(basename "$dir"); surface=${name%_*}; speed=${name##*_}; speed=${speed%kmh}
  awk -F, -v s="$surface" -v v="$speed" '($1 == "cpx_front" || $1 == "cpx_rear") && NR > 1 { e[$2] += 10 ^ ($4 / 10) / 2; if (!($2 in seen)) { order[++n] = $2; seen[$2] = 1 } }
       END { for (i = 1; i <= n; i++) printf "%s,%s,%s,%.2f\n", s, v, order[i], 10 * log(e[order[i]]) / log(10) }' "$dir/spectrum.csv" >> "$out/spectra.csv.tmp"
done
mv "$out/spectra.csv.tmp" "$out/spectra.csv"

# Per run: CPX level, the A-weighted peak third octave, and the octave levels at 500 Hz, 1, 2 and
# 4 kHz relative to the 1 kHz octave (the form of CNOSSOS-EU's car rolling-noise shape).
measured() {  # surface speed -> measured value or NA
  case "$1_$2" in
    sma11_50) echo "92.8 [C1]" ;; dac11_50) echo "89.8 [C1]" ;;
    sma11_80) echo "99.6 [C2]" ;; eacc_80) echo "98.5 [C2]" ;; *) echo "NA -" ;;
  esac
}
echo "surface,speed_kmh,cpx_LAeq_dB,measured_dB,source,peak_band_hz,oct500_rel_dB,oct1k_rel_dB,oct2k_rel_dB,oct4k_rel_dB" > "$out/validation.csv.tmp"
for dir in "$out"/*_*kmh; do
  name=$(basename "$dir"); surface=${name%_*}; speed=${name##*_}; speed=${speed%kmh}
  read -r value source <<< "$(measured "$surface" "$speed")"
  shape=$(awk -F, -v s="$surface" -v v="$speed" '$1 == s && $2 == v {
        f = $3 + 0; e = 10 ^ ($4 / 10); if (e > best) { best = e; peak = f }
        # octave of centre F holds the third octaves F/1.26, F, F*1.26
        for (o = 500; o <= 4000; o *= 2) if (f > o / 1.3 && f < o * 1.3) oct[o] += e }
      END { ref = oct[1000]; printf "%s", peak;
            for (o = 500; o <= 4000; o *= 2) printf ",%s", (oct[o] > 0 ? sprintf("%.1f", 10 * log(oct[o] / ref) / log(10)) : "NA") }' "$out/spectra.csv")
  echo "$surface,$speed,$(cpx "$dir"),$value,$source,$shape" >> "$out/validation.csv.tmp"
done
sort -t, -k2,2n -k1,1 "$out/validation.csv.tmp" > "$out/validation.csv"; rm "$out/validation.csv.tmp"

{
  echo "| surface | speed (km/h) | CPX L_Aeq computed (dB(A)) | measured (dB(A)) | difference (dB) | source | A-weighted peak band (Hz) | octaves 500 / 1k / 2k / 4k Hz re 1 kHz (dB) |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
  awk -F, 'NR > 1 { d = ($4 == "NA") ? "—" : sprintf("%+.1f", $3 - $4);
                    printf "| %s | %s | %s | %s | %s | %s | %s | %s / %s / %s / %s |\n", $1, $2, $3, ($4 == "NA" ? "—" : $4), d, ($5 == "-" ? "—" : $5), $6, $7, $8, $9, $10 }' "$out/validation.csv"
} > "$out/validation_table.md"
# The A-weighted CPX spectra of every surface at 80 km/h in one figure, drawn from spectra.csv.
cat > "$out/cpx_spectra_surfaces.gp" <<'GP'
# Drawn by tools/validation.sh from spectra.csv; run `gnuplot cpx_spectra_surfaces.gp` to redraw.
set terminal pngcairo size 1000,560 noenhanced font 'DejaVu Sans,10'
set output 'cpx_spectra_surfaces.png'
set datafile separator ','
set grid
set logscale x
set xrange [90:5600]
set xtics (100, 200, 315, 500, 800, 1250, 2000, 3150, 5000)
set xlabel 'third-octave band (Hz)'
set ylabel 'LpA, CPX (energy mean of front and rear), dB(A)'
set key outside right
set title 'CASE_TITLE'
surfaces = system("awk -F, 'NR > 1 && $2 == 80 && !seen[$1]++ { printf \"%s \", $1 }' spectra.csv")
set yrange [50:110]
# More surfaces than the default palette has colours: the ninth and later dashed.
dash(i) = i > 8 ? 2 : 1
plot for [i=1:words(surfaces)] 'spectra.csv' using (strcol(1) eq word(surfaces, i) && $2 == 80 ? $3 : 1/0):4 \
       with linespoints lc i dt dash(i) pt 7 ps 0.6 title word(surfaces, i)
GP
title="205/55 R16, $(basename "$case" .toml), 80 km/h, 3200 N, 0.2 s${VALIDATION_SET:+, $VALIDATION_SET}, on each library surface"
sed -i "s|CASE_TITLE|${title//\"/}|" "$out/cpx_spectra_surfaces.gp"
if command -v gnuplot > /dev/null; then (cd "$out" && gnuplot cpx_spectra_surfaces.gp); fi
cat "$out/validation_table.md"

#!/usr/bin/env bash
# The two tyre models side by side: the Kropp plate with its Winkler tread and the
# seed's two-layer elastic tyre, the same 205/55 R16 at 80 km/h on the same road (dac11) under the
# same CPX load, 0.2 s each. Writes docs/tyre_models/: models.csv (the headline numbers), the
# CPX rear third-octave spectra of both (cpx_spectra.csv/.gp/.png), their point mobilities
# (point_mobility.gp/.png, from docs/greens/*/mobility.csv, which `rollnoise greens` wrote), and
# each run's contact-pressure map and Fig. 5a analogue (copied from the runs). Needs a built tree
# (bash tools/setup.sh); about 6 minutes on 2 cores with an empty table cache.
set -euo pipefail
cd "$(dirname "$0")/.."
rollnoise=build/tools/rollnoise/rollnoise
out=docs/tyre_models
runs=out/tyre_models
mkdir -p "$out" "$runs"
for model in plate two_layer; do
  CI=true "$rollnoise" simulate "models/cases/${model}_rough_80kmh.toml" --out "$runs/$model" --set output.wav=false
  cp "$runs/$model/pressure_map.png" "$out/${model}_pressure_map.png"
  cp "$runs/$model/greens_circumference.png" "$out/${model}_greens_circumference.png"
done
python3 - "$runs" "$out" <<'PY'
import csv, json, math, sys
runs, out = sys.argv[1], sys.argv[2]
rows = []
bands = {}
for model in ("plate", "two_layer"):
    s = json.load(open(f"{runs}/{model}/summary.json"))
    forces = [float(r["total_force"]) for r in csv.DictReader(open(f"{runs}/{model}/contact.csv"))]
    mean = sum(forces) / len(forces)
    std = math.sqrt(sum((f - mean) ** 2 for f in forces) / len(forces))
    rows.append([model, s["levels"]["cpx_front"]["LAeq_dB"], s["levels"]["cpx_rear"]["LAeq_dB"],
                 s["sound_power"]["LwA_dB"], mean, std, min(forces), max(forces), s["patch_length_m"],
                 s["rolling_resistance_N"], s["contact_time_s"], s["wall_time_s"]])
    for r in csv.DictReader(open(f"{runs}/{model}/spectrum.csv")):
        if r["receiver"] == "cpx_rear":
            bands.setdefault(float(r["band_hz"]), {})[model] = float(r["LpA_dB"])
with open(f"{out}/models.csv", "w") as f:
    f.write("model,cpx_front_LAeq_dB,cpx_rear_LAeq_dB,LwA_dB,mean_total_force_N,total_force_std_N,"
            "min_total_force_N,max_total_force_N,patch_length_m,rolling_resistance_N,contact_time_s,wall_time_s\n")
    for r in rows:
        f.write(",".join(r[:1] + [f"{v:.6g}" for v in r[1:]]) + "\n")
with open(f"{out}/cpx_spectra.csv", "w") as f:
    f.write("band_hz,plate_LpA_dB,two_layer_LpA_dB\n")
    for b in sorted(bands):
        if 100 <= b <= 5000:
            f.write(f"{b:g},{bands[b]['plate']:.3f},{bands[b]['two_layer']:.3f}\n")
PY
cat > "$out/cpx_spectra.gp" <<'GP'
# Drawn by tools/tyre_models.sh from cpx_spectra.csv; run `gnuplot cpx_spectra.gp` to redraw.
set terminal pngcairo size 900,500 noenhanced font 'DejaVu Sans,10'
set output 'cpx_spectra.png'
set datafile separator ','
set grid
set logscale x
set xrange [90:5600]
set xtics (100, 200, 315, 500, 800, 1250, 2000, 3150, 5000)
set xlabel 'third-octave band (Hz)'
set ylabel 'LpA at the rear CPX microphone (dB(A))'
set key top left
set title '205/55 R16, 80 km/h, dac11, 3200 N, 0.2 s: plate + Winkler tread against the two-layer tyre'
plot 'cpx_spectra.csv' skip 1 using 1:2 with linespoints pt 7 title 'plate (Kropp) + Winkler tread', \
     '' skip 1 using 1:3 with linespoints pt 5 title 'two-layer elastic tyre (Larsson & Kropp)'
GP
cat > "$out/point_mobility.gp" <<'GP'
# Drawn by tools/tyre_models.sh from docs/greens/{plate,two_layer}/mobility.csv (rollnoise greens);
# run `gnuplot point_mobility.gp` in docs/tyre_models to redraw.
set terminal pngcairo size 900,500 noenhanced font 'DejaVu Sans,10'
set output 'point_mobility.png'
set datafile separator ','
set grid
set logscale xy
set xrange [10:6000]
set xlabel 'frequency (Hz)'
set ylabel '|Y| point mobility (m/(N s))'
set key bottom left
set title 'Point mobility at the belt centre: plate (belt alone; its Winkler tread is added in the contact) and two-layer (tread surface)'
plot '../greens/plate/mobility.csv' skip 1 using ($2 == 0 && $1 > 0 ? $1 : 1/0):(sqrt($3**2 + $4**2)) with lines lw 2 title 'plate', \
     '../greens/two_layer/mobility.csv' skip 1 using ($2 == 0 && $1 > 0 ? $1 : 1/0):(sqrt($3**2 + $4**2)) with lines lw 2 title 'two-layer'
GP
(cd "$out" && gnuplot cpx_spectra.gp && gnuplot point_mobility.gp)
cat "$out/models.csv"

#!/usr/bin/env bash
# The contact force per third octave with the texture contact law against the rigid cells
# ([rolling] contact_law, docs/physics/contact.md#contact-below-the-cell): the plate and the
# two-layer tyre at 80 km/h on dac11, sma11 and the chip seal (read at 0.45 mm, under a quarter of a
# cell), 0.2 s each without radiation, and for the plate a third run on the cells' highest
# points with a stiff law (E = 1e11 Pa: the plate's [tyre.tread] youngs_modulus serves the law
# alone), which separates where a cell meets the road from the law's compliance. The two-layer
# tyre's tread modulus is also its tread layer's, so it has no such run.
# Writes out/contact_law/{force_bands.csv, force_bands.md} and one run folder per case (a
# finished run is kept: delete its folder to redo it). Needs a built tree (bash tools/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
rollnoise=${ROLLNOISE:-build/tools/rollnoise/rollnoise}
out=${CONTACT_LAW_OUT:-out/contact_law}
duration=${CONTACT_LAW_DURATION:-0.2}
mkdir -p "$out"
declare -A tyre_case=([plate]=models/cases/plate_rough_80kmh.toml [two_layer]=models/cases/two_layer_rough_80kmh.toml)
run() {  # tyre surface law
  local dir="$out/$1_$2_$3"
  [[ -f "$dir/summary.json" ]] && return
  local extra=()
  [[ "$2" == chipseal ]] && extra+=(--set road.sample_spacing=0.00045)
  case "$3" in
    rigid) ;;
    texture) extra+=(--set 'rolling.contact_law="texture"') ;;
    stiff) extra+=(--set 'rolling.contact_law="texture"' --set tyre.tread.youngs_modulus=1e11) ;;
  esac
  "$rollnoise" simulate "${tyre_case[$1]}" --out "$dir" --set "road.surface=models/surfaces/$2.toml" \
    --set rolling.duration="$duration" --set radiation.enabled=false --set output.plots=false "${extra[@]}" > /dev/null
}
for tyre in plate two_layer; do
  for surface in dac11 sma11 chipseal; do
    for law in rigid texture; do run "$tyre" "$surface" "$law"; done
  done
done
run plate dac11 stiff
# The total contact force's third-octave levels (Welch: Hann segments of 1024 steps, half
# overlapped, mean removed), per run, and the differences.
/usr/bin/python3 - "$out" <<'PY'
import csv, json, math, os, sys
import numpy as np
out = sys.argv[1]
bands = [250, 315, 400, 500, 630, 800, 1000, 1250, 1600, 2000, 2500, 3150, 4000, 5000]
def levels(run):
    rows = list(csv.DictReader(open(os.path.join(out, run, "contact.csv"))))
    t = np.array([float(r["time"]) for r in rows]); f = np.array([float(r["total_force"]) for r in rows])
    f -= f.mean(); dt = t[1] - t[0]; n = 1024; w = np.hanning(n); step = n // 2
    spectra = [np.abs(np.fft.rfft(w * f[i:i + n]))**2 for i in range(0, len(f) - n + 1, step)]
    psd = np.mean(spectra, axis=0) * 2 * dt / np.sum(w**2)
    freq = np.fft.rfftfreq(n, dt); df = freq[1]
    return [10 * math.log10(max(psd[(freq >= b * 2**(-1/6)) & (freq < b * 2**(1/6))].sum() * df, 1e-30)) for b in bands]
rows = []
for tyre in ["plate", "two_layer"]:
    for surface in ["dac11", "sma11", "chipseal"]:
        rigid, texture = levels(f"{tyre}_{surface}_rigid"), levels(f"{tyre}_{surface}_texture")
        s = json.load(open(os.path.join(out, f"{tyre}_{surface}_texture", "summary.json")))
        rows.append((tyre, surface, "texture - rigid", [b - a for a, b in zip(rigid, texture)], s))
    if tyre == "plate":
        stiff = levels(f"{tyre}_dac11_stiff")
        rigid, texture = levels(f"{tyre}_dac11_rigid"), levels(f"{tyre}_dac11_texture")
        rows.append((tyre, "dac11", "stiff law - rigid (where a cell meets the road)", [b - a for a, b in zip(rigid, stiff)], None))
        rows.append((tyre, "dac11", "texture - stiff law (the law's compliance)", [b - a for a, b in zip(stiff, texture)], None))
with open(os.path.join(out, "force_bands.csv"), "w") as f:
    f.write("tyre,surface,comparison," + ",".join(f"dB_{b}Hz" for b in bands) + "\n")
    for tyre, surface, what, d, _ in rows:
        f.write(f"{tyre},{surface},{what}," + ",".join(f"{x:.1f}" for x in d) + "\n")
with open(os.path.join(out, "force_bands.md"), "w") as f:
    f.write("| tyre | surface | change of the total contact force (dB) | " + " | ".join(str(b) for b in bands) + " Hz |\n")
    f.write("| --- | --- | --- | " + " | ".join("---" for _ in bands) + " |\n")
    for tyre, surface, what, d, _ in rows:
        f.write(f"| {tyre} | {surface} | {what} | " + " | ".join(f"{x:+.1f}".replace("-", "−") for x in d) + " |\n")
    f.write("\n| tyre | surface | laws computed | law time (s) | step loop, texture / rigid (s) | largest cell force (N) | table end (N) |\n| --- | --- | --- | --- | --- | --- | --- |\n")
    for tyre, surface, what, d, s in rows:
        if s is None: continue
        r = json.load(open(os.path.join(out, f"{tyre}_{surface}_rigid", "summary.json")))
        law = s["texture_contact_law"]
        f.write(f"| {tyre} | {surface} | {law['cells']} | {law['seconds']:.1f} | {s['step_loop_time_s']:.2f} / {r['step_loop_time_s']:.2f} | {law['largest_cell_force_N']:.1f} | {law['force_cap_N']:.1f} |\n")
print(open(os.path.join(out, "force_bands.md")).read())
PY

#!/usr/bin/env bash
# Issue 10: why the dense asphalt (dac11), with 9-12 dB less texture than SMA 11 in every band,
# gets 9-14 dB more contact force at 250-630 Hz (docs/validation.md, "The dense asphalt's
# excess"). For each surface: the road's MPD, RMS and height skewness, and the third-octave
# levels of the total contact force from 0.1 s of plate_rough_80kmh with the radiation off.
#   bash tools/diagnostics/surface_construction.sh [OUT]      (default out/surface_construction)
# The variants are written to OUT/surfaces/: dac11 rebuilt with the aggregate model's rolled
# ("negative") construction, same stones, and the Winkler tread swapped for the half-space tread.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-out/surface_construction}
bin=build/tools/rollnoise/rollnoise
mkdir -p "$out/surfaces"
# The rolled variant: stones pressed from a common top plane (the model's "negative"), with the
# mastic at 20 % (the deepest fill the rolled construction allows here gives MPD 0.55 mm).
sed -e 's/^texture = "positive"/texture = "negative"/' -e 's/^binder_level = 0.7 /binder_level = 0.2 /' \
  models/surfaces/dac11.toml > "$out/surfaces/dac11_rolled.toml"
surfaces=(models/surfaces/dac11.toml models/surfaces/iso10844.toml models/surfaces/sma11.toml
          "$out/surfaces/dac11_rolled.toml")
halfspace=(--set tyre.tread.type=halfspace --set tyre.tread.youngs_modulus=4e6 --set tyre.tread.poisson_ratio=0.45)
run() { # name surface [extra settings...]
  local name=$1 surface=$2; shift 2
  "$bin" simulate models/cases/plate_rough_80kmh.toml --out "$out/$name" --force --no-cache \
    --set road.surface="$surface" --set rolling.duration=0.1 --set radiation.enabled=false \
    --set output.wav=false --set output.fields=none "$@" >/dev/null
}
names=()
for s in "${surfaces[@]}"; do
  n=$(basename "$s" .toml)
  "$bin" road "$s" --out "$out/road_$n" --force >/dev/null
  run "$n" "$s"; names+=("$n")
done
# The measured chip seal (CAPTIF laser profile), the most positive real texture at hand: its
# height statistics only.
"$bin" road data/surfaces/captif/20211011_aylesbury_dec_station_0.dat --out "$out/road_captif_0" --force >/dev/null
names+=(captif_0)
run dac11_halfspace models/surfaces/dac11.toml "${halfspace[@]}"; names+=(dac11_halfspace)
run sma11_halfspace models/surfaces/sma11.toml "${halfspace[@]}"; names+=(sma11_halfspace)
python3 - "$out" "${names[@]}" <<'PY'
import cmath, csv, json, math, sys
out, names = sys.argv[1], sys.argv[2:]
def moments(path):
    z = [float(r['z']) for r in csv.DictReader(open(path))]
    m = sum(z) / len(z); s = math.sqrt(sum((v - m) ** 2 for v in z) / len(z))
    return s, sum((v - m) ** 3 for v in z) / len(z) / s ** 3
print('surface            MPD (mm)  RMS (mm)  skewness')
for n in names:
    try:
        d = json.load(open(f'{out}/road_{n}/summary.json'))
    except FileNotFoundError:
        continue
    s, k = moments(f'{out}/road_{n}/road.csv')
    print(f'{n:18s} {d["mpd_m"]*1e3:8.2f}  {s*1e3:8.3f}  {k:8.2f}')
centres = [250, 315, 400, 500, 630, 800, 1000, 1250, 1600, 2000]
def force_bands(path):
    rows = list(csv.DictReader(open(path)))
    f = [float(r['total_force']) for r in rows]; n = len(f)
    dt = float(rows[1]['time']) - float(rows[0]['time'])
    m = sum(f) / n
    w = [0.5 - 0.5 * math.cos(2 * math.pi * i / n) for i in range(n)]
    wn = sum(v * v for v in w) / n
    x = [(f[i] - m) * w[i] for i in range(n)]
    levels = []
    for c in centres:
        lo, hi = c * 2 ** (-1 / 6), c * 2 ** (1 / 6)
        p = 0.0
        for k in range(math.ceil(lo * n * dt), math.ceil(hi * n * dt)):
            s = sum(x[i] * cmath.exp(-2j * math.pi * k * i / n) for i in range(n))
            p += 2 * abs(s) ** 2 / (n * n * wn)   # one-sided mean square in the bin (Hann, power-normalised)
        levels.append(10 * math.log10(p) if p > 0 else float('nan'))
    return levels
print('\ntotal contact force, third octaves, dB re 1 N (0.1 s, one Hann segment)')
print('band (Hz)          ' + ' '.join(f'{c:6d}' for c in centres))
for n in names:
    if n != 'captif_0':
        print(f'{n:18s} ' + ' '.join(f'{v:6.1f}' for v in force_bands(f'{out}/{n}/contact.csv')))
PY

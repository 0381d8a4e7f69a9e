#!/usr/bin/env bash
# The radiation cache's benchmark (issue 12, "Performance"): a study (default
# models/studies/surfaces_cpx.toml, 0.2 s a case) run cold, with an empty cache in a temporary
# folder, then warm, every case run again (--restart) with the cache the cold run filled. Prints
# per case the wall time, the contact stage (summary.json contact_time_s), the radiation
# (radiation.time_s) and the anchors found in the cache, and checks the issue's target: warm,
# each case costs no more than its contact stage plus 5 s.
#
# Usage: bench/study_cache.sh [STUDY.toml] [OUT]
#   SURFACES="dac11 sma11"  only these surfaces of the study's road.surface list (a subset, for
#                           a machine where the whole study takes too long)
#   SPEEDS="22.222"         only these speeds (m/s) of its rolling.speed list
#   THREADS=N               cases side by side (default: the study's default, one per core)
#   BIN=PATH                the rollnoise to run (default: build/, as built by tools/setup.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
study=${1:-models/studies/surfaces_cpx.toml}
out=${2:-out/bench_study_cache}
bin=${BIN:-$PWD/build/tools/rollnoise/rollnoise}
cache=$(mktemp -d "${TMPDIR:-/tmp}/rollnoise-bench-cache.XXXXXX")
trap 'rm -rf "$cache"' EXIT
mkdir -p "$out"

# The study, with its lists cut to SURFACES and SPEEDS, and its relative paths made absolute
# (the copy lives in $out).
python3 - "$study" "$out/study.toml" "${SURFACES:-}" "${SPEEDS:-}" <<'PY'
import pathlib, re, sys
source, target, surfaces, speeds = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]), sys.argv[3].split(), sys.argv[4].split()
text = source.read_text()
text = re.sub(r'"(\.\./[^"]+)"', lambda m: '"' + str((source.parent / m.group(1)).resolve()) + '"', text)
def keep(key, wanted, match):
    global text
    if not wanted:
        return
    pattern = re.compile(r'^' + re.escape(key) + r'\s*=\s*\[(.*?)\]', re.S | re.M)
    items = [i.strip() for i in pattern.search(text).group(1).split(',') if i.strip()]
    kept = [i for i in items if any(match(i, w) for w in wanted)]
    if not kept:
        sys.exit(f"study_cache.sh: none of {wanted} is in {key}")
    text = pattern.sub(key + ' = [' + ', '.join(kept) + ']', text)
keep('road.surface', surfaces, lambda item, w: item.strip('"').endswith('/' + w + '.toml'))
keep('rolling.speed', speeds, lambda item, w: float(item) == float(w))
pathlib.Path(target).write_text(text)
PY

threads=()
if [[ -n ${THREADS:-} ]]; then threads=(--threads "$THREADS"); fi
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); study $study${SURFACES:+, surfaces: $SURFACES}${SPEEDS:+, speeds: $SPEEDS}"
seconds() { local s e; s=$(date +%s.%N); "$@" >/dev/null; e=$(date +%s.%N); echo "$e - $s" | bc; }
echo "cold (empty cache): $(seconds "$bin" study "$out/study.toml" --out "$out/cold" --restart --cache "$cache" "${threads[@]}") s"
"$bin" cache list --cache "$cache" | tail -n 1
echo "warm (--restart, the cache filled): $(seconds "$bin" study "$out/study.toml" --out "$out/warm" --restart --cache "$cache" "${threads[@]}") s"

python3 - "$out" <<'PY'
import json, pathlib, sys
out = pathlib.Path(sys.argv[1])
failed = 0
for run in ("cold", "warm"):
    print(f"{run}:")
    print(f"  {'case':44s} {'wall s':>8s} {'contact s':>10s} {'radiation s':>12s} {'cached':>8s} {'wall - contact':>15s}")
    for case in sorted((out / run / "cases").iterdir()):
        s = json.loads((case / "summary.json").read_text())
        r = s.get("radiation", {})
        wall, contact, radiation = s["wall_time_s"], s.get("contact_time_s", 0.0), r.get("time_s", 0.0)
        cached = f"{r.get('anchors_from_cache', 0)}/{r.get('anchors', 0)}"
        mark = ""
        if run == "warm":
            ok = wall <= contact + 5.0
            failed += not ok
            mark = "  ok" if ok else "  MISSES the target (contact + 5 s)"
        print(f"  {case.name:44s} {wall:8.1f} {contact:10.1f} {radiation:12.1f} {cached:>8s} {wall - contact:15.1f}{mark}")
    # The cold run's levels equal the warm run's (the cache changes no result).
    if run == "warm":
        same = all((out / "cold" / "cases" / c.name / "spectrum.csv").read_bytes() == (c / "spectrum.csv").read_bytes()
                   for c in (out / "warm" / "cases").iterdir())
        print(f"  spectra of the warm run identical to the cold run's: {same}")
print("target (warm: wall <= contact + 5 s):", "met by every case" if failed == 0 else f"missed by {failed} cases")
PY

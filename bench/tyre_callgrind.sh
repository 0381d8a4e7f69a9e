#!/usr/bin/env bash
# Instruction counts of the rolling tyre's hot loops (issue 13), under valgrind's callgrind:
# repeatable on a shared, noisy machine where wall times spread by 2×. A short run of a case
# (default plate_rough_80kmh, 0.003 s: 35 steps) is counted only inside the per-step calls:
# the contact problem (PMatrixLcpSolver::solve), the history engine (ModalHistoryEngine::history
# and ::advance) and the response stage with the streamed outputs (TyreStepOutputs::take).
# Prints each one's instructions per step.
#   bash bench/tyre_callgrind.sh [CASE [DURATION_S]]
# ROLLNOISE_EXE picks the binary (default: the Release build without assertions, build-bench/).
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/bench_binary.sh
command -v valgrind >/dev/null || { echo "valgrind is not installed (apt-get install valgrind)" >&2; exit 1; }
case=${1:-models/cases/plate_rough_80kmh.toml}
duration=${2:-0.003}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
functions=("rollnoise::PMatrixLcpSolver::solve*" "rollnoise::ModalHistoryEngine::history*"
           "rollnoise::ModalHistoryEngine::advance*" "rollnoise::TyreStepOutputs::take*")
toggles=()
for f in "${functions[@]}"; do toggles+=(--toggle-collect="$f"); done
CI=true valgrind --tool=callgrind --callgrind-out-file="$out/callgrind.out" "${toggles[@]}" \
  "$exe" simulate "$case" --out "$out/run" --set rolling.duration="$duration" --set radiation.enabled=false \
  --set output.plots=false >/dev/null 2>"$out/valgrind.log"
steps=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['settings']['steps'] + 1)" "$out/run/summary.json")
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(basename "$case" .toml), $steps steps"
callgrind_annotate --inclusive=yes --threshold=100 "$out/callgrind.out" 2>/dev/null | python3 -c '
import re, sys
steps = int(sys.argv[1])
wanted = {"PMatrixLcpSolver::solve": "contact problem (LCP solve)",
          "ModalHistoryEngine::history": "history engine, u0 of the contact step",
          "ModalHistoryEngine::advance": "modal advance (the contact engine and the response stage together)",
          "TyreStepOutputs::take": "response stage + streamed outputs (with its own modal advance)"}
seen = {}
for line in sys.stdin:
    m = re.match(r"\s*([\d,]+)\s", line)
    if not m:
        continue
    count, name = int(m.group(1).replace(",", "")), line
    for key, label in wanted.items():
        if "rollnoise::" + key + "(" in name and label not in seen:
            seen[label] = count
for label in wanted.values():
    if label in seen:
        print(f"{label}: {seen[label] / steps / 1e6:.2f} M instructions per step")
    else:
        print(f"{label}: not called")
' "$steps"

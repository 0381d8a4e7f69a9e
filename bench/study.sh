#!/usr/bin/env bash
# The study benchmark of issue 12: a study (default models/studies/surfaces_cpx.toml, 0.2 s a
# case) run from scratch (--restart), then run again (every case finished: what resuming costs),
# then with 1 and 2 MPI ranks when mpirun is there. Prints the wall times, and per case the
# wall, contact and radiation times from the cases' summary.json. Uses build/ as built by
# tools/setup.sh. Usage: bench/study.sh [STUDY.toml] [OUT]
set -euo pipefail
cd "$(dirname "$0")/.."
study=${1:-models/studies/surfaces_cpx.toml}
out=${2:-out/bench_study}
bin=build/tools/rollnoise/rollnoise
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
seconds() { local s e; s=$(date +%s.%N); "$@" >/dev/null; e=$(date +%s.%N); echo "$e - $s" | bc; }
echo "cold (--restart): $(seconds "$bin" study "$study" --out "$out" --restart) s"
echo "rerun (all cases finished): $(seconds "$bin" study "$study" --out "$out") s"
python3 - "$out" <<'PY'
import json, pathlib, sys
for case in sorted(pathlib.Path(sys.argv[1], "cases").iterdir()):
    s = json.loads((case / "summary.json").read_text())
    print(f"{case.name:40s} wall {s['wall_time_s']:7.1f} s  contact {s.get('contact_time_s', 0):7.1f} s  "
          f"radiation {s.get('radiation', {}).get('time_s', 0):7.1f} s")
PY
if command -v mpirun >/dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  for n in 1 2; do
    echo "mpirun -n $n: $(seconds mpirun -n "$n" --oversubscribe "$bin" study "$study" --out "$out-mpi$n" --restart) s"
  done
fi

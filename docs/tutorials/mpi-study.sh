#!/usr/bin/env bash
# The tutorial "Run a study on a cluster with MPI" (mpi-study.md), command for command, on two
# ranks of this machine. Run from anywhere: bash docs/tutorials/mpi-study.sh
# ROLLNOISE, OUT and ROLLNOISE_TUTORIAL_QUICK as in docs/tutorials/common.sh.
TUTORIAL=mpi-study
source "$(dirname "$0")/common.sh"

if ! command -v mpirun >/dev/null 2>&1; then
  echo "mpi-study: skipped: mpirun not found (OpenMPI: sudo apt-get install openmpi-bin libopenmpi-dev, as tools/setup.sh does, then rebuild)"
  exit 0
fi
# A program built without MPI refuses to run under mpirun -n 2 (exit status 2): skip, saying why.
# (ldd's output is read whole first: under pipefail, `ldd | grep -q` fails whenever grep stops
# reading before ldd has written everything.)
libraries=$(ldd "$ROLLNOISE" 2>/dev/null || true)
if [[ $libraries != *libmpi* ]]; then
  echo "mpi-study: skipped: $ROLLNOISE is not built with MPI (install libopenmpi-dev openmpi-bin, then rebuild: bash tools/setup.sh)"
  exit 0
fi
# OpenMPI refuses to run as root (a container, CI) unless told that it is meant.
if [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
# `mpirun ... PROGRAM study FILE ...` as the page writes it, with quick mode's study file.
mpirun() {
  local args=("$@") i arg start=$SECONDS
  for ((i = 0; i < ${#args[@]}; ++i)); do
    if [[ ${args[i]} == "$ROLLNOISE" ]]; then
      local rest=()
      while IFS= read -r -d '' arg; do rest+=("$arg"); done < <(quick_arguments "${args[@]:i+1}")
      args=("${args[@]:0:i+1}" "${rest[@]}")
      break
    fi
  done
  echo "+ mpirun ${args[*]}" >&2
  command mpirun "${args[@]}"
  echo "$TUTORIAL: mpirun took $((SECONDS - start)) s" >&2
}

# 1. The study on two ranks.
mpirun -n 2 --oversubscribe "$ROLLNOISE" study docs/tutorials/mpi-study.toml --out "$OUT"/mpi
grep '"ranks"' "$OUT"/mpi/summary.json

# 2. The same study on this machine alone, with two cases side by side on threads.
rollnoise study docs/tutorials/mpi-study.toml --out "$OUT"/threads --threads 2

# 3. The results do not depend on how the cases were spread (the wall times aside).
cut -d, -f1-8 "$OUT"/mpi/results.csv > "$OUT"/mpi_results.csv
cut -d, -f1-8 "$OUT"/threads/results.csv > "$OUT"/threads_results.csv
cmp "$OUT"/mpi_results.csv "$OUT"/threads_results.csv && cmp "$OUT"/mpi/spectra.csv "$OUT"/threads/spectra.csv && echo "the same results"

# 4. Resuming: a case lost (as if its node had failed) is run again; the others are kept.
rm -r "$OUT"/mpi/cases/surface-pa16_speed-30.556
mpirun -n 2 --oversubscribe "$ROLLNOISE" study docs/tutorials/mpi-study.toml --out "$OUT"/mpi

# Sourced by each tutorial script (docs/tutorials/<name>.sh); not a tutorial of its own.
#
# Each script runs its page's commands, in the page's order, from the repository root. The page
# writes `build/tools/rollnoise/rollnoise` and `out/tutorials/<name>`; the script writes
# `rollnoise` (the function below) or "$ROLLNOISE", and "$OUT". tests/docs/test_tutorials.cpp
# checks that the two agree line for line.
#
#   ROLLNOISE  the program (default build/tools/rollnoise/rollnoise)
#   OUT        the output root (default out/tutorials/<name>)
#   ROLLNOISE_TUTORIAL_QUICK=1
#              the test's quick mode: the same commands on a short run (0.01 s of rolling, the
#              band to 1 kHz, a coarse radiation mesh), one calibration start and a shorter
#              band, and a study file with the same settings added to its [set] table. The
#              outputs have the same files and columns; the numbers are not the page's.
# A relative ROLLNOISE or OUT is taken from the folder the script was started in; a ROLLNOISE
# without a slash is looked up on the PATH.
set -euo pipefail

tutorial_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tutorial_caller=$PWD
ROLLNOISE=${ROLLNOISE:-$tutorial_root/build/tools/rollnoise/rollnoise}
if [[ $ROLLNOISE != */* ]]; then
  ROLLNOISE=$(command -v "$ROLLNOISE" || echo "$ROLLNOISE")   # a name on the PATH
elif [[ $ROLLNOISE != /* ]]; then
  ROLLNOISE=$tutorial_caller/$ROLLNOISE
fi
if [[ -n ${OUT:-} ]]; then
  [[ $OUT == /* ]] || OUT=$tutorial_caller/$OUT
else
  OUT=out/tutorials/$TUTORIAL
fi
QUICK=${ROLLNOISE_TUTORIAL_QUICK:-0}
cd "$tutorial_root"
if [[ ! -x $ROLLNOISE ]]; then
  echo "$TUTORIAL: no program at $ROLLNOISE: build it first (bash tools/demo.sh or bash tools/test.sh), or set ROLLNOISE" >&2
  exit 2
fi
mkdir -p "$OUT"

# The settings of quick mode, as `section.key=value`.
quick_settings=(rolling.duration=0.01 rolling.band_top=1000 rolling.points_lateral=6
                radiation.mesh_around=32 radiation.mesh_across=2 radiation.sidewall_rings=4
                radiation.anchor_spacing=500 radiation.contact_refinement=3)

# A copy of a study file for quick mode, in $OUT, with the quick settings added to its [set]
# table. Prints the copy's path. (The tutorials' study files name other files from the
# repository root, which the program finds from the current folder wherever the copy lies.)
quick_study_file() {
  local source=$1 copy
  copy=$OUT/quick-$(basename "$source")
  grep -q '^\[set\]' "$source" || { echo "quick mode: $source has no [set] table" >&2; return 2; }
  awk -v settings="${quick_settings[*]}" '
    BEGIN {
      n = split(settings, s, " ")
      for (i = 1; i <= n; ++i) { eq = index(s[i], "="); key[i] = substr(s[i], 1, eq - 1); value[i] = substr(s[i], eq + 1); quick[key[i]] = 1 }
    }
    /^\[/ { in_set = ($0 ~ /^\[set\]/) }
    in_set && /=/ { k = $0; sub(/[ \t]*=.*/, "", k); if (k in quick) next }
    { print }
    /^\[set\]/ { for (i = 1; i <= n; ++i) print key[i] " = " value[i] }' "$source" >"$copy"
  printf '%s\n' "$copy"
}

# The arguments of a rollnoise command, changed for quick mode (unchanged otherwise).
quick_arguments() {
  local args=("$@") i
  if [[ $QUICK == 1 ]]; then
    case ${args[0]} in
      simulate)
        for i in "${quick_settings[@]}"; do args+=(--set "$i"); done ;;
      study)
        args[1]=$(quick_study_file "${args[1]}") ;;
      calibrate)
        args+=(--starts 1 --frequency-range 20:1000) ;;
    esac
  fi
  printf '%s\0' "${args[@]}"
}

# `rollnoise VERB ...` as the page writes it; says what it ran and how long it took.
rollnoise() {
  local args=() arg start=$SECONDS
  while IFS= read -r -d '' arg; do args+=("$arg"); done < <(quick_arguments "$@")
  echo "+ rollnoise ${args[*]}" >&2
  "$ROLLNOISE" "${args[@]}"
  echo "$TUTORIAL: rollnoise $1 took $((SECONDS - start)) s" >&2
}

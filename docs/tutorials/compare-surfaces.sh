#!/usr/bin/env bash
# The tutorial "Compare surfaces at several speeds" (compare-surfaces.md), command for command.
# Run from anywhere: bash docs/tutorials/compare-surfaces.sh
# ROLLNOISE, OUT and ROLLNOISE_TUTORIAL_QUICK as in docs/tutorials/common.sh.
TUTORIAL=compare-surfaces
source "$(dirname "$0")/common.sh"

# 1. The study: 3 surfaces x 3 speeds, each case a tyre run.
rollnoise study docs/tutorials/compare-surfaces.toml --out "$OUT"/study

# 2. Run again: every finished case is kept, and the results are written anew.
rollnoise study docs/tutorials/compare-surfaces.toml --out "$OUT"/study

# 3. The table: surface, speed, LAeq at the CPX front microphone and the sound power level.
cut -d, -f1-3,7 "$OUT"/study/results.csv

# 4. Each case reruns alone from the case file the study wrote.
rollnoise simulate "$OUT"/study/cases/surface-sma11_speed-22.222/case.toml --out "$OUT"/sma11_80kmh
cmp "$OUT"/study/cases/surface-sma11_speed-22.222/spectrum.csv "$OUT"/sma11_80kmh/spectrum.csv && echo "the same spectrum"

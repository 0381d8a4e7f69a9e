#!/usr/bin/env bash
# The tutorial "Calibrate my tyre from measured mobilities" (calibrate-tyre.md), command for
# command. Run from anywhere: bash docs/tutorials/calibrate-tyre.sh
# ROLLNOISE, OUT and ROLLNOISE_TUTORIAL_QUICK as in docs/tutorials/common.sh.
TUTORIAL=calibrate-tyre
source "$(dirname "$0")/common.sh"

# 1. Fit the plate tyre to a point and a transfer mobility given as CSV files.
rollnoise calibrate models/tyres/passenger_205_55R16.toml \
    --data data/mobility/tyre_point_mobility.csv data/mobility/tyre_transfer_mobility.csv \
    --out "$OUT"/from_csv

# 2. The same measurement as a UFF file (dataset 58): the nodes' positions on the command line.
rollnoise calibrate models/tyres/passenger_205_55R16.toml --data data/mobility/tyre_frfs.uff \
    --node 1=0,0.09 --node 2=0.1,0.09 --out "$OUT"/from_uff

# 3. The fitted values: the header calibrate wrote above the model file's own text.
sed -n '1,/^# The rest of the file/p' "$OUT"/from_csv/calibrated.toml

# 4. Roll the calibrated tyre, and the model file's own, on the dense asphalt at 80 km/h.
rollnoise simulate models/cases/plate_rough_80kmh.toml --set tyre.file="$OUT"/from_csv/calibrated.toml --out "$OUT"/rough_calibrated
rollnoise simulate models/cases/plate_rough_80kmh.toml --out "$OUT"/rough_estimated

# 5. The levels of the two runs.
grep -h -A3 '"cpx_front": {' "$OUT"/rough_calibrated/summary.json "$OUT"/rough_estimated/summary.json

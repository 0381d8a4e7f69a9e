#!/usr/bin/env bash
# The tutorial "Auralise a pass-by" (auralise-pass-by.md), command for command.
# Run from anywhere: bash docs/tutorials/auralise-pass-by.sh
# ROLLNOISE, OUT and ROLLNOISE_TUTORIAL_QUICK as in docs/tutorials/common.sh.
TUTORIAL=auralise-pass-by
source "$(dirname "$0")/common.sh"

# 1. The tyre on the dense asphalt concrete at 80 km/h, half a second of rolling: the sound at
#    the CPX and SPB microphones, and the pass-by.
rollnoise simulate models/cases/plate_rough_80kmh.toml --set rolling.duration=0.5 --out "$OUT"/80kmh

# 2. The same at 50 km/h.
rollnoise simulate models/cases/plate_rough_80kmh.toml --set rolling.duration=0.5 --set rolling.speed=13.889 --out "$OUT"/50kmh

# 3. The WAV files measured as recordings: the full scale is read from their comment.
rollnoise analyse "$OUT"/80kmh/cpx_front.wav --out "$OUT"/cpx_front_80kmh
rollnoise analyse "$OUT"/80kmh/spb_passby.wav --out "$OUT"/passby_80kmh
rollnoise analyse "$OUT"/50kmh/spb_passby.wav --out "$OUT"/passby_50kmh

# 4. The levels side by side: what simulate reported, and what analyse measured in its WAV files.
grep -h -A3 '"cpx_front": {' "$OUT"/80kmh/summary.json
grep -h -A3 '"ch1": {' "$OUT"/cpx_front_80kmh/summary.json
grep -h LAFmax "$OUT"/passby_80kmh/summary.json "$OUT"/passby_50kmh/summary.json

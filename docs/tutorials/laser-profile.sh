#!/usr/bin/env bash
# The tutorial "My own laser profile: its texture and its noise" (laser-profile.md), command
# for command. Run from anywhere: bash docs/tutorials/laser-profile.sh
# ROLLNOISE, OUT and ROLLNOISE_TUTORIAL_QUICK as in docs/tutorials/common.sh.
TUTORIAL=laser-profile
source "$(dirname "$0")/common.sh"

# 1. The profile's texture: MPD, ETD and the third-octave texture spectrum.
rollnoise road data/surfaces/captif/20211011_aylesbury_dec_station_0.dat --out "$OUT"/profile

# 2. A surface file from the measured texture spectrum, bands from 2.5 mm up.
awk -F, 'NR > 1 && $1 >= 0.0025 { w = w sep $1; l = l sep sprintf("%.1f", $2); sep = ", " }
  END { print "# Synthesised from the texture spectrum of a measured laser profile"
        print "type = \"texture\""
        print "wavelengths = [" w "]    # m"
        print "levels = [" l "]    # dB re 1 um"
        print "sample_spacing = 0.001"
        print "length = 8.0"
        print "width = 0.3"
        print "seed = 1" }' "$OUT"/profile/texture.csv > "$OUT"/my_surface.toml

# 3. The synthesised surface analysed as the profile was: its spectrum against the target.
rollnoise road "$OUT"/my_surface.toml --out "$OUT"/surface

# 4. The tyre rolling on it at 80 km/h: the contact, the levels, the spectra, the sound.
rollnoise simulate models/cases/plate_rough_80kmh.toml --set road.surface="$OUT"/my_surface.toml --out "$OUT"/noise

# 5. The same tyre on the reference dense asphalt concrete, to compare.
rollnoise simulate models/cases/plate_rough_80kmh.toml --out "$OUT"/dac11

# 6. The A-weighted levels at the CPX front microphone, band by band, side by side.
awk -F, 'FNR == 1 { f++ } $1 == "cpx_front" { L[f, $2] = $4; if (f == 1) band[++n] = $2 }
  END { printf "%8s %10s %10s\n", "band_Hz", "my_surface", "dac11"
        for (i = 1; i <= n; ++i) {
          printf "%8s %10.1f %10.1f\n", band[i], L[1, band[i]], L[2, band[i]]
          for (j = 1; j <= 2; ++j) sum[j] += 10 ^ (L[j, band[i]] / 10) }
        printf "%8s %10.1f %10.1f\n", "sum", 10 * log(sum[1]) / log(10), 10 * log(sum[2]) / log(10) }' \
  "$OUT"/noise/spectrum.csv "$OUT"/dac11/spectrum.csv | tee "$OUT"/compare_cpx_front.txt

# 7. The two spectra drawn (the script stays beside the figure, to restyle and redraw).
cat > "$OUT"/compare_cpx_front.gp <<'GP'
set terminal pngcairo size 900,500 noenhanced font 'DejaVu Sans,10'
set output 'compare_cpx_front.png'
set title 'Tyre at 80 km/h: A-weighted third octaves at the CPX front microphone'
set logscale x
set grid
set xlabel 'third-octave band (Hz)'
set ylabel 'L_pA (dB(A) re 20 uPa)'
set yrange [50:*]
set key top left
plot 'compare_cpx_front.txt' every ::1 using 1:2 with linespoints pt 7 title 'my surface (from the laser profile)', \
     '' every ::1 using 1:3 with linespoints pt 5 title 'dac11 (dense asphalt concrete 0/11)'
GP
(cd "$OUT" && gnuplot compare_cpx_front.gp)

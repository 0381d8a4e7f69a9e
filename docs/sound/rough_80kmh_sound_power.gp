# Drawn by rollnoise from sound_power.csv of `rollnoise simulate models/cases/plate_rough_80kmh.toml`, renamed rough_80kmh_sound_power.*; run `gnuplot rough_80kmh_sound_power.gp` to redraw.
set terminal pngcairo size 1000,550 noenhanced font 'DejaVu Sans,10'
set output 'rough_80kmh_sound_power.png'
set datafile separator ','
set grid
set logscale x
set xlabel 'third-octave band (Hz)'
set ylabel 'sound power level (dB re 1 pW)'
set key top left
set title 'Sound power radiated by the tyre (into the half-space above the road)'
plot 'rough_80kmh_sound_power.csv' skip 1 using 1:2 with linespoints lw 1.5 pt 7 ps 0.6 title 'L_W', \
     '' skip 1 using 1:3 with linespoints lw 1.5 pt 5 ps 0.6 title 'L_WA'

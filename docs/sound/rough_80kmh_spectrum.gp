# Drawn by rollnoise from spectrum.csv of `rollnoise simulate models/cases/plate_rough_80kmh.toml`, renamed rough_80kmh_spectrum.*; run `gnuplot rough_80kmh_spectrum.gp` to redraw.
set terminal pngcairo size 1000,550 noenhanced font 'DejaVu Sans,10'
set output 'rough_80kmh_spectrum.png'
set datafile separator ','
set grid
set logscale x
set xlabel 'third-octave band (Hz)'
set ylabel 'L_pA (dB(A) re 20 uPa)'
set key outside right
set title 'A-weighted third-octave band levels'
# The 60 dB below the loudest band: the quiet low bands would squash the rest.
stats 'rough_80kmh_spectrum.csv' skip 1 using 4 nooutput
set yrange [STATS_max - 60 : STATS_max + 5]
plot 'rough_80kmh_spectrum.csv' skip 1 using ((strcol(1) eq 'cpx_front') ? $2 : 1/0):4 with linespoints lw 1.5 pt 7 ps 0.6 title 'cpx_front', \
     'rough_80kmh_spectrum.csv' skip 1 using ((strcol(1) eq 'cpx_rear') ? $2 : 1/0):4 with linespoints lw 1.5 pt 7 ps 0.6 title 'cpx_rear', \
     'rough_80kmh_spectrum.csv' skip 1 using ((strcol(1) eq 'spb') ? $2 : 1/0):4 with linespoints lw 1.5 pt 7 ps 0.6 title 'spb', \
     'rough_80kmh_spectrum.csv' skip 1 using ((strcol(1) eq 'spb_passby') ? $2 : 1/0):4 with linespoints lw 1.5 pt 7 ps 0.6 title 'spb_passby'

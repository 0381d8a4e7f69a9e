# The library's porous asphalts: normal-incidence absorption and the ground effect of a point
# source 0.05 m high heard 1.2 m high 7.5 m away, per third octave (rollnoise road output).
# Made 2026-11-27 on a 2-core AMD EPYC (Debian 12) by:
#   rollnoise road models/surfaces/pa16.toml --out pa16 --length 1 --ground-effect 0.05,7.5,1.2
#   rollnoise road models/surfaces/pa2l.toml --out pa2l --length 2 --ground-effect 0.05,7.5,1.2
# with the CSVs copied here as pa16_*.csv and pa2l_*.csv; then `gnuplot porous_absorption.gp`.
set terminal pngcairo size 1000,420 noenhanced font 'DejaVu Sans,10'
set output 'porous_absorption.png'
set datafile separator ','
set multiplot layout 1,2
set grid
set logscale x
set xrange [100:10000]
set xlabel 'frequency (Hz)'
set title 'Normal-incidence absorption'
set ylabel 'alpha'
set yrange [0:1]
plot 'pa16_absorption.csv' skip 1 using 1:2 with linespoints pt 7 title 'pa16 (one layer)', \
     'pa2l_absorption.csv' skip 1 using 1:2 with linespoints pt 5 title 'pa2l (two layers)'
set title 'Ground effect against a rigid road (band values)'
set ylabel 'level change (dB)'
set yrange [-15:12]
plot 'pa16_ground_effect.csv' skip 1 using 1:3 with linespoints pt 7 title 'pa16', \
     'pa2l_ground_effect.csv' skip 1 using 1:3 with linespoints pt 5 title 'pa2l'
unset multiplot

# Drawn by rollnoise greens from mobility.csv; run `gnuplot mobility.gp` to redraw.
set terminal pngcairo size 1000,750 noenhanced font 'DejaVu Sans,10'
set output 'mobility.png'
set datafile separator ','
set grid
set key top right
set multiplot layout 2,1 title 'Mobility of the two_layer: force at x = 0, response at distance d along the circumference'
set ylabel '|Y| (dB re 1 m/(N s))'
plot 'mobility.csv' using 1:(abs($2 - (0)) < 1e-9 ? 20*log10(sqrt($3**2 + $4**2)) : 1/0) with lines lw 1.5 title 'd = 0 m', \
     'mobility.csv' using 1:(abs($2 - (0.050000000000000003)) < 1e-9 ? 20*log10(sqrt($3**2 + $4**2)) : 1/0) with lines lw 1.5 title 'd = 0.05 m', \
     'mobility.csv' using 1:(abs($2 - (0.10000000000000001)) < 1e-9 ? 20*log10(sqrt($3**2 + $4**2)) : 1/0) with lines lw 1.5 title 'd = 0.1 m', \
     'mobility.csv' using 1:(abs($2 - (0.20000000000000001)) < 1e-9 ? 20*log10(sqrt($3**2 + $4**2)) : 1/0) with lines lw 1.5 title 'd = 0.2 m', \
     'mobility.csv' using 1:(abs($2 - (0.5)) < 1e-9 ? 20*log10(sqrt($3**2 + $4**2)) : 1/0) with lines lw 1.5 title 'd = 0.5 m'
set xlabel 'frequency (Hz)'
set ylabel 'phase (deg)'
set yrange [-180:180]
set ytics 90
plot 'mobility.csv' using 1:(abs($2 - (0)) < 1e-9 ? atan2($4, $3)*180/pi : 1/0) with lines lw 1.5 notitle, \
     'mobility.csv' using 1:(abs($2 - (0.050000000000000003)) < 1e-9 ? atan2($4, $3)*180/pi : 1/0) with lines lw 1.5 notitle, \
     'mobility.csv' using 1:(abs($2 - (0.10000000000000001)) < 1e-9 ? atan2($4, $3)*180/pi : 1/0) with lines lw 1.5 notitle, \
     'mobility.csv' using 1:(abs($2 - (0.20000000000000001)) < 1e-9 ? atan2($4, $3)*180/pi : 1/0) with lines lw 1.5 notitle, \
     'mobility.csv' using 1:(abs($2 - (0.5)) < 1e-9 ? atan2($4, $3)*180/pi : 1/0) with lines lw 1.5 notitle
unset multiplot

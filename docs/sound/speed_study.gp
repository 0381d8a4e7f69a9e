# Drawn by tools/speed_study.sh from speed_study.csv; run `gnuplot speed_study.gp` to redraw.
set terminal pngcairo size 900,550 noenhanced font 'DejaVu Sans,10'
set output 'speed_study.png'
set datafile separator ','
set grid
set logscale x
set xrange [40:125]
set xtics (50, 63, 80, 100, 125)
set xlabel 'speed (km/h)'
set ylabel 'LAeq at the CPX microphones (dB(A))'
set key bottom right
# L = A + B lg(V): B is the slope in dB per decade of speed.
f(x) = a + b * log10(x)
fit f(x) 'speed_study.csv' skip 1 using 1:(($4 + $5) / 2) via a, b
set title sprintf('CPX level against speed, 205/55 R16 on the rough road: %.1f dB per decade (bands to 1.6 kHz)', b)
plot 'speed_study.csv' skip 1 using 1:2 with linespoints pt 7 title 'cpx_front, whole band', \
     '' skip 1 using 1:3 with linespoints pt 7 title 'cpx_rear, whole band', \
     '' skip 1 using 1:(($4 + $5) / 2) with points pt 5 ps 1.2 title 'CPX mean, bands to 1.6 kHz', \
     f(x) with lines dt 2 title 'fit A + B lg V'

# Drawn by rollnoise from level_speed_cpx_front.dat (one block per series: speed km/h, LAeq dB);
# run `gnuplot level_speed_cpx_front.gp` to redraw. Lines: L = a + b lg(v/80 km/h).
set terminal pngcairo size 1000,600 noenhanced font 'DejaVu Sans,10'
set output 'level_speed_cpx_front.png'
set grid
set logscale x
set key outside right
set xlabel 'speed (km/h)'
set ylabel 'LAeq at cpx_front (dB)'
set xrange [45.454909090909084:121.00176000000002]
set xtics (50, 80, 110)
set title 'Study two_surfaces: level against speed'
plot 'level_speed_cpx_front.dat' index 0 using 1:2 with points pt 7 lc 1 notitle, 98.75732764322639 + 26.677355235051504*log10(x/80) with lines lw 1.5 lc 1 title 'dac11: b = 26.7', \
     'level_speed_cpx_front.dat' index 1 using 1:2 with points pt 7 lc 2 notitle, 95.63002357134037 + 28.074982538708287*log10(x/80) with lines lw 1.5 lc 2 title 'sma11: b = 28.1'

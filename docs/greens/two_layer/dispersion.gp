# Drawn by rollnoise greens from dispersion.csv; run `gnuplot dispersion.gp` to redraw.
set terminal pngcairo size 1000,650 noenhanced font 'DejaVu Sans,10'
set output 'dispersion.png'
set datafile separator ','
set title 'Free waves of the two_layer tyre, lateral order n = 1: log10 |H_zz|; its ridges are the dispersion curves'
set xlabel 'circumferential wavenumber k (rad/m)'
set ylabel 'frequency (Hz)'
set logscale y
set yrange [20:6000]
set view map
set pm3d map interpolate 1,1
set palette rgb 33,13,10
set cblabel 'log10 |H_zz| (m/Pa)'
splot 'dispersion.csv' skip 1 using 1:2:3 with pm3d notitle

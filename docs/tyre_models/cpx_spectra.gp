# Drawn by tools/tyre_models.sh from cpx_spectra.csv; run `gnuplot cpx_spectra.gp` to redraw.
set terminal pngcairo size 900,500 noenhanced font 'DejaVu Sans,10'
set output 'cpx_spectra.png'
set datafile separator ','
set grid
set logscale x
set xrange [90:5600]
set xtics (100, 200, 315, 500, 800, 1250, 2000, 3150, 5000)
set xlabel 'third-octave band (Hz)'
set ylabel 'LpA at the rear CPX microphone (dB(A))'
set key top left
set title '205/55 R16, 80 km/h, dac11, 3200 N, 0.2 s: plate + Winkler tread against the two-layer tyre'
plot 'cpx_spectra.csv' skip 1 using 1:2 with linespoints pt 7 title 'plate (Kropp) + Winkler tread', \
     '' skip 1 using 1:3 with linespoints pt 5 title 'two-layer elastic tyre (Larsson & Kropp)'

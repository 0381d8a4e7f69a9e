# Drawn by rollnoise from spectra_speed_22.222.dat (one block per case: band Hz, LpA dB).
set terminal pngcairo size 1000,600 noenhanced font 'DejaVu Sans,10'
set output 'spectra_speed_22.222.png'
set grid
set logscale x
set key outside right
set xlabel 'third-octave band (Hz)'
set ylabel 'LpA at cpx_front (dB)'
set title 'Study two_surfaces: spectra at 22.222 m/s'
plot 'spectra_speed_22.222.dat' index 0 using 1:2 with linespoints lw 1.5 pt 7 ps 0.5 title 'dac11', \
     'spectra_speed_22.222.dat' index 1 using 1:2 with linespoints lw 1.5 pt 7 ps 0.5 title 'sma11'

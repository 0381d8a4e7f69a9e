# Drawn by rollnoise from difference_to_reference.dat (one block per case: band Hz, LpA - LpA of the reference, dB).
set terminal pngcairo size 1000,600 noenhanced font 'DejaVu Sans,10'
set output 'difference_to_reference.png'
set grid
set logscale x
set key outside right
set xlabel 'third-octave band (Hz)'
set ylabel 'LpA - LpA on dac11 at cpx_front (dB)'
set title 'Study two_surfaces: difference to the reference surface'
plot 'difference_to_reference.dat' index 0 using 1:2 with linespoints lw 1.5 pt 7 ps 0.5 title 'sma11, 13.889', \
     'difference_to_reference.dat' index 1 using 1:2 with linespoints lw 1.5 pt 7 ps 0.5 title 'sma11, 22.222', \
     'difference_to_reference.dat' index 2 using 1:2 with linespoints lw 1.5 pt 7 ps 0.5 title 'sma11, 30.556'

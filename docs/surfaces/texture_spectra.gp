# Drawn by tools/surface_library.sh from texture_spectra.csv; run `gnuplot texture_spectra.gp` to redraw.
set terminal pngcairo size 1000,600 noenhanced font 'DejaVu Sans,10'
set output 'texture_spectra.png'
set datafile separator ','
set grid
set logscale x
set xrange [2:200]
set yrange [10:70]
set title 'Texture level spectra of the surface library (ISO 13473-4, analysed by rollnoise road)'
set xlabel 'texture wavelength (mm)'
set ylabel 'L_tx (dB re 1 um)'
set key outside right
surfaces = 'dac11 sma11 sma8 pa16 pa2l thin6 chipseal iso10844 eacc tined captif_fine'
measured = 'captif_0 captif_1 captif_transverse'
plot for [s in surfaces] 'texture_spectra.csv' using (strcol(1) eq s ? $2*1000 : 1/0):3 \
       with linespoints pt 7 ps 0.6 title s, \
     for [s in measured] 'texture_spectra.csv' using (strcol(1) eq s ? $2*1000 : 1/0):3 \
       with lines dt 2 lw 2 title s.' (measured)'

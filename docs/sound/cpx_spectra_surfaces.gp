# Drawn by tools/validation.sh from its spectra.csv (here the 80 km/h rows, cpx_spectra_surfaces.csv); run `gnuplot cpx_spectra_surfaces.gp` to redraw.
set terminal pngcairo size 1000,560 noenhanced font 'DejaVu Sans,10'
set output 'cpx_spectra_surfaces.png'
set datafile separator ','
set grid
set logscale x
set xrange [90:5600]
set xtics (100, 200, 315, 500, 800, 1250, 2000, 3150, 5000)
set xlabel 'third-octave band (Hz)'
set ylabel 'LpA, CPX (energy mean of front and rear), dB(A)'
set key outside right
set title '205/55 R16 plate tyre, 80 km/h, 3200 N, 0.2 s, on each library surface'
surfaces = system("awk -F, 'NR > 1 && $2 == 80 && !seen[$1]++ { printf \"%s \", $1 }' cpx_spectra_surfaces.csv")
set yrange [50:110]
# More surfaces than the default palette has colours: the ninth and later dashed.
dash(i) = i > 8 ? 2 : 1
plot for [i=1:words(surfaces)] 'cpx_spectra_surfaces.csv' using (strcol(1) eq word(surfaces, i) && $2 == 80 ? $3 : 1/0):4 \
       with linespoints lc i dt dash(i) pt 7 ps 0.6 title word(surfaces, i)

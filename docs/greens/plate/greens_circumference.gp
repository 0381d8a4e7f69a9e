# The belt's Green's function along the circumference (cf. Larsson 2000, Fig. 5a).
set terminal pngcairo size 1000,500 noenhanced font 'DejaVu Sans,10'
set output 'greens_circumference.png'
set datafile separator ','
set grid
set key top right
set title 'Green function of the plate along the circumference, unit impulse at x = 0 (mid-width)'
set xlabel 'position around the tyre, x (m)'
set ylabel 'g (mm/(N s))'
plot for [c=2:5] 'greens_circumference.csv' using 1:(column(c)*1e3) with lines lw 1.5 title columnheader(c)

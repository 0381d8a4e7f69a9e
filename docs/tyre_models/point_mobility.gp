# Drawn by tools/tyre_models.sh from docs/greens/{plate,two_layer}/mobility.csv (rollnoise greens);
# run `gnuplot point_mobility.gp` in docs/tyre_models to redraw.
set terminal pngcairo size 900,500 noenhanced font 'DejaVu Sans,10'
set output 'point_mobility.png'
set datafile separator ','
set grid
set logscale xy
set xrange [10:6000]
set xlabel 'frequency (Hz)'
set ylabel '|Y| point mobility (m/(N s))'
set key bottom left
set title 'Point mobility at the belt centre: plate (belt alone; its Winkler tread is added in the contact) and two-layer (tread surface)'
plot '../greens/plate/mobility.csv' skip 1 using ($2 == 0 && $1 > 0 ? $1 : 1/0):(sqrt($3**2 + $4**2)) with lines lw 2 title 'plate', \
     '../greens/two_layer/mobility.csv' skip 1 using ($2 == 0 && $1 > 0 ? $1 : 1/0):(sqrt($3**2 + $4**2)) with lines lw 2 title 'two-layer'

# The reference patterned tyre's tread (models/tyres/passenger_205_55R16_patterned.toml), as a run
# draws it: run in the output folder of
#   rollnoise simulate models/cases/plate_patterned_rough_80kmh.toml --out out/patterned
# (it reads that folder's tread_pattern.csv); the PNG is copied here as tread_pattern_205_55R16.png.
# Drawn by rollnoise from tread_pattern.csv; run `gnuplot tread_pattern.gp` to redraw.
# The tread unrolled: s around the circumference (2πR = 1.98549 m) in four strips of a
# quarter turn, y across from the tread's centre line; height 0 is the block surface.
set terminal pngcairo size 1200,900 noenhanced font 'DejaVu Sans,10'
set output 'tread_pattern_205_55R16.png'
set datafile separator ','
set palette defined (0 '#440154', 1 '#21918c', 2 '#fde725', 3 'white')
set cblabel 'tread height (mm)'
set ylabel 'y (mm)'
set yrange [-70:70]
set multiplot layout 4,1 title "plate tyre: tread pattern, unrolled (a quarter turn per strip)"
set xrange [0:496.372]
plot 'tread_pattern.csv' skip 1 using ($1*1e3):($2*1e3):($3*1e3) with image notitle
set xrange [496.372:992.743]
plot 'tread_pattern.csv' skip 1 using ($1*1e3):($2*1e3):($3*1e3) with image notitle
set xrange [992.743:1489.11]
plot 'tread_pattern.csv' skip 1 using ($1*1e3):($2*1e3):($3*1e3) with image notitle
set xrange [1489.11:1985.49]
set xlabel 's around the circumference (mm)'
plot 'tread_pattern.csv' skip 1 using ($1*1e3):($2*1e3):($3*1e3) with image notitle
unset multiplot

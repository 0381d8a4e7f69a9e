# The paper's Fig. 4b: the coupled points (c = 0.4) on the random road; top point 1, bottom
# point 2, with the reference surface (crosses).
set terminal pngcairo size 1200,700 noenhanced font 'DejaVu Sans,10'
set output 'fig4b_coupled_random.png'
set datafile separator ','
set grid
set key top right
set xlabel 'time (s)'
set ylabel 'vertical position (mm)'
set multiplot layout 2,1 title 'Two coupled SDOFs (c = 0.4) on a random road (Larsson 2000, Fig. 4b)'
set title 'point 1'
plot '../larsson2000_coupled_random/contact.csv' using 1:($3*1e3) with lines lw 2 lc rgb '#1f77b4' title 'contact point 1', \
     '' using 1:($2*1e3) every 30 with points pt 2 ps 0.7 lc rgb '#d62728' title 'reference surface'
set title 'point 2'
plot '../larsson2000_coupled_random/contact.csv' using 1:($6*1e3) with lines lw 2 lc rgb '#1f77b4' title 'contact point 2', \
     '' using 1:($5*1e3) every 30 with points pt 2 ps 0.7 lc rgb '#d62728' title 'reference surface'
unset multiplot

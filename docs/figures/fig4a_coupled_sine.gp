# The paper's Fig. 4a: the two contact points on the sine road, coupled (c = 0.4) against
# uncoupled (c = 0), with the reference surface (crosses).
set terminal pngcairo size 1200,700 noenhanced font 'DejaVu Sans,10'
set output 'fig4a_coupled_sine.png'
set datafile separator ','
set grid
set key top right
set xlabel 'time (s)'
set ylabel 'vertical position (mm)'
set multiplot layout 2,1 title 'Two SDOFs 0.01 m apart on a sine road: coupled (c = 0.4) and uncoupled (Larsson 2000, Fig. 4a)'
set title 'point 1'
plot '../larsson2000_coupled_sine/contact.csv' using 1:($3*1e3) with lines lw 2 lc rgb '#1f77b4' title 'coupled', \
     '../larsson2000_uncoupled_sine/contact.csv' using 1:($3*1e3) with lines lw 2 dt 2 lc rgb '#2ca02c' title 'uncoupled', \
     '../larsson2000_coupled_sine/contact.csv' using 1:($2*1e3) every 30 with points pt 2 ps 0.7 lc rgb '#d62728' title 'reference surface'
set title 'point 2'
plot '../larsson2000_coupled_sine/contact.csv' using 1:($6*1e3) with lines lw 2 lc rgb '#1f77b4' title 'coupled', \
     '../larsson2000_uncoupled_sine/contact.csv' using 1:($6*1e3) with lines lw 2 dt 2 lc rgb '#2ca02c' title 'uncoupled', \
     '../larsson2000_coupled_sine/contact.csv' using 1:($5*1e3) every 30 with points pt 2 ps 0.7 lc rgb '#d62728' title 'reference surface'
unset multiplot

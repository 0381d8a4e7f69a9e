# The paper's Fig. 3: displacement of the SDOF contact point (line) against the reference
# surface (crosses), on the sine road (left) and the random road (right).
# Reads the demo's outputs: run from out/demo/figures (tools/demo.sh does).
set terminal pngcairo size 1200,450 noenhanced font 'DejaVu Sans,10'
set output 'fig3_sdof.png'
set datafile separator ','
set grid
set key top right
set xlabel 'time (s)'
set ylabel 'vertical position (mm)'
set multiplot layout 1,2 title 'SDOF contact point on two surfaces (Larsson 2000, Fig. 3; Table 1 parameters)'
set title 'sine road'
plot '../larsson2000_sdof_sine/contact.csv' using 1:($3*1e3) with lines lw 2 lc rgb '#1f77b4' title 'contact point', \
     '' using 1:($2*1e3) every 30 with points pt 2 ps 0.7 lc rgb '#d62728' title 'reference surface'
set title 'random road'
plot '../larsson2000_sdof_random/contact.csv' using 1:($3*1e3) with lines lw 2 lc rgb '#1f77b4' title 'contact point', \
     '' using 1:($2*1e3) every 30 with points pt 2 ps 0.7 lc rgb '#d62728' title 'reference surface'
unset multiplot

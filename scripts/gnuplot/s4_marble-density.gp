# S4: density of the marble value u for each turbulence amplitude a,
# against the arcsine density of undisturbed stripes.
# Called as: gnuplot -e "dir='results/s4_marble'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/density.png'
set datafile separator "\t"
set xlabel "u"
set ylabel "density"
set key top center
set grid
set xrange [0:1]
set yrange [0:*]
set title "Marble: density of u (20 bins, mean over seeds)"
f = dir.'/u_density.tsv'
arcsine(u) = 1 / (pi * sqrt(u * (1 - u)))
set samples 400
plot for [c=2:5] f using 1:c with linespoints lw 2 pt 7 ps 0.6 title columnheader(c), \
     arcsine(x) with lines dt 2 lc rgb "black" title "arcsine law 1/(pi sqrt(u(1-u)))"

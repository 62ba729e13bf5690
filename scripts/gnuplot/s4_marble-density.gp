# S4: density of the marble value u for each turbulence amplitude a,
# against the arcsine density of undisturbed stripes.
# Called as: gnuplot -e "dir='results/s4_marble'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/density.png'
set datafile separator "\t"
set datafile columnheaders
set xlabel "u"
set ylabel "density"
set key top center
set grid
set xrange [0:1]
set yrange [0:*]
set title "Marble: density of u (20 bins, mean over seeds)"
f = dir.'/u_density.tsv'
# The arcsine law averaged over each 0.05-wide bin, the quantity the
# histogram estimates: (F(u + h) - F(u - h)) / 2h with F(u) = 2/pi asin(sqrt u).
F(u) = 2 / pi * asin(sqrt(u < 0 ? 0 : u > 1 ? 1 : u))
h = 0.025
# One curve per column other than "u", addressed by its header name.
ys = system("head -1 '".f."' | tr '\\t' '\\n' | grep -vx u | sed 's/.*/\"&\"/' | tr '\\n' ' '")
plot for [i=1:words(ys)] f using "u":(column(word(ys, i))) with linespoints lw 2 pt 7 ps 0.6 title word(ys, i), \
     f using "u":((F(column("u") + h) - F(column("u") - h)) / (2 * h)) with lines dt 2 lw 2 lc rgb "black" \
       title "arcsine law, bin average"

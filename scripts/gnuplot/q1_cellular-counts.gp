# Q1: fraction of unit cubes with m feature points under the paper's
# closest-p rule and inverse-CDF sampling, against Poisson(lambda).
# Called as: gnuplot -e "dir='results/q1_cellular'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/counts.png'
set datafile separator "\t"
f = dir.'/counts.tsv'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set key top right
set grid ytics
set xlabel "points per cube m"
set ylabel "fraction of cubes"
set xrange [-0.5:15.5]
set title "Count per cube: paper's rule vs inverse-CDF vs Poisson (mean over seeds)"
plot f using 2:xtic(1) every ::0::15 title "Poisson p(m)", \
     '' using 3 every ::0::15 title "closest-p rule (paper)", \
     '' using 4 every ::0::15 title "inverse CDF"

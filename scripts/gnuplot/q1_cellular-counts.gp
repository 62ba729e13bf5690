# Q1: fraction of unit cubes with m feature points under the paper's
# closest-p rule (smaller m on ties, and larger m on ties) and inverse-CDF
# sampling, against Poisson(lambda).
# Called as: gnuplot -e "dir='results/q1_cellular'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/counts.png'
set datafile separator "\t"
set datafile columnheaders
f = dir.'/counts.tsv'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set key top right
set grid ytics
set xlabel "points per cube m"
set ylabel "fraction of cubes"
set xrange [-0.5:14.5]
set title "Count per cube: paper's rule vs inverse-CDF vs Poisson (mean over seeds)"
plot f using "poisson":xtic(strcol("m")) every ::0::14 title "Poisson p(m)", \
     '' using "closest" every ::0::14 title "closest-p rule (paper), smaller m on ties", \
     '' using "closest_last" every ::0::14 title "closest-p rule, larger m on ties", \
     '' using "inverse_cdf" every ::0::14 title "inverse CDF"

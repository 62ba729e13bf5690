# C2 (Fig 4.5, 4.6 right): histograms of the optimised angles, 500 bins
# (expected count 1.02 per bin), per pattern (rows) and objective (columns).
# Called as: gnuplot -e "dir='results/c2_ks_vs_chisq'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,9"
set output dir.'/hist.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name: hist_PATTERN.tsv is theta, ks, chisq, kuiper
set multiplot layout 2,3 title "C2: histograms of the 512 optimised angles, 500 bins (first seed)"
pats = "flower x"
objs = "KS chi-square Kuiper"
cols = "ks chisq kuiper"
set xrange [0:2*pi]
set yrange [0:5]
set xlabel "angle (rad)"
set ylabel "count"
do for [i=1:2] {
  do for [o=1:3] {
    f = dir.'/hist_'.word(pats, i).'.tsv'
    set title word(pats, i)." / ".word(objs, o)." term"
    plot f using "theta":(column(word(cols, o))) with impulses lc rgb (o == 1 ? "blue" : o == 2 ? "red" : "dark-green") notitle, \
         512.0 / 500 with lines lc rgb "#ff69b4" notitle
  }
}
unset multiplot

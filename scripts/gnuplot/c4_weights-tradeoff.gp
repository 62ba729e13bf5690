# C4 (Table 4.1, Fig 4.8): E_KS against E_Con over the sweep of w1 / w2 (w1 + w2 = 1),
# with the thesis's six pairs as printed and swapped (left); both terms
# against w1 / w2 (right). Means and sd over seeds.
# Called as: gnuplot -e "dir='results/c4_weights'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,10"
set output dir.'/tradeoff.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name (nl_study_cheng_summary_alloc)
s = dir.'/sweep.tsv'
t = dir.'/table41_runs.tsv'
set multiplot layout 1,2 title "C4: weight sweep, E = w1 E_{KS} + w2 E_{Con}"
set xlabel "E_{Con}"
set ylabel "E_{KS}"
set logscale y
set grid
set key top right
plot s using "E_con":"E_ks":"E_con_sd":"E_ks_sd" with xyerrorbars lc rgb "gray40" pt 7 ps 0.6 title "sweep", \
     s using "E_con":"E_ks" with lines lc rgb "gray40" notitle, \
     t using (strcol("reading") eq "printed" ? column("E_con") : NaN):"E_ks" with points pt 5 ps 1.2 lc rgb "blue" title "Table 4.1 printed", \
     t using (strcol("reading") eq "swapped" ? column("E_con") : NaN):"E_ks" with points pt 9 ps 1.4 lc rgb "red" title "Table 4.1 swapped", \
     t using (strcol("reading") eq "printed" ? column("E_con") : NaN):"E_ks":"panel" with labels offset 0.8,0.6 tc rgb "blue" notitle, \
     t using (strcol("reading") eq "swapped" ? column("E_con") : NaN):"E_ks":"panel" with labels offset 0.8,-0.6 tc rgb "red" notitle
set logscale x
set xlabel "w1 / w2 (w1 + w2 = 1)"
set format x "10^{%L}"
set ylabel "E_{KS}"
set y2label "E_{Con}"
set ytics nomirror
set y2tics
unset logscale y2
set key top center
plot s using (column("w1")/column("w2")):"E_ks":"E_ks_sd" with yerrorlines lc rgb "blue" pt 7 ps 0.6 title "E_{KS}", \
     s using (column("w1")/column("w2")):"E_con":"E_con_sd" axes x1y2 with yerrorlines lc rgb "red" pt 7 ps 0.6 title "E_{Con}"
unset multiplot

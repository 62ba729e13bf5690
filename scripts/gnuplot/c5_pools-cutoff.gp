# C5 (sec. 3.5.2): number of complete-linkage clusters of the 1000 input
# samples against the cutoff (cos/sin distance), per texture; the thesis's
# initial K as dashed lines, its (not comparable) cutoffs as points.
# Called as: gnuplot -e "dir='results/c5_pools'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,10"
set output dir.'/cutoff.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name: texture, low_levels, cutoff, K
f = dir.'/cutoff_k.tsv'
# the cutoff of the rows of texture t at low_levels l; NaN elsewhere
sel(t, l) = strcol("texture") eq t && column("low_levels") == l ? column("cutoff") : NaN
set title "C5: initial K against the cutoff (complete linkage on (cos, sin) of the low angles)"
set xlabel "cutoff (chord distance)"
set ylabel "clusters K"
set logscale y
set grid
set key top right
# the other low/high split is measured only when C5 runs it (alt_low_levels;
# quick yes, paper scale no): in the key only when its rows are there
stats f using (column("low_levels") == 2 ? 1 : 0) nooutput
alt = STATS_sum > 0 ? "erosion, levels 1-2" : ""
plot f using (sel("erosion", 1)):"K" with linespoints pt 7 ps 0.5 lc rgb "brown" title "erosion", \
     f using (sel("marble", 1)):"K" with linespoints pt 7 ps 0.5 lc rgb "blue" title "marble", \
     f using (sel("cloud", 1)):"K" with linespoints pt 7 ps 0.5 lc rgb "dark-green" title "cloud", \
     f using (sel("erosion", 2)):"K" with linespoints pt 6 ps 0.5 dt 2 lc rgb "brown" title alt, \
     30 with lines dt 2 lc rgb "brown" title "thesis K0 erosion (30)", \
     39 with lines dt 2 lc rgb "blue" title "thesis K0 marble (39)", \
     20 with lines dt 2 lc rgb "dark-green" title "thesis K0 cloud (20)", \
     '-' using "cutoff":"K":"colour" with points pt 9 ps 1.5 lc rgb variable title "thesis cutoffs (other units)"
cutoff	K	colour
18.6	30	10824234
19.5	39	255
15.5	20	25600
e

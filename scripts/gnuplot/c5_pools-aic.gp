# C5 (sec. 3.5.3): AIC and BIC against the number of mixture components along
# the selection path (first seed), per texture, for the literal thesis cutoff
# (path from K = 1) and the cutoff matched to the thesis's initial K. The
# thesis's initial and final K (Tables 4.2-4.4, read from gmm.tsv's paper_*
# columns) are drawn as vertical lines; its AIC (about -1.5e7 .. -2.5e7) is
# off this scale and stated in each panel.
# Called as: gnuplot -e "dir='results/c5_pools'" THIS
set terminal pngcairo size 900,640 font "DejaVu Sans,10"
set output dir.'/aic.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name: texture, low_levels, cutoff_rule, K, AIC, BIC, ...
f = dir.'/aic_path.tsv'
g = dir.'/gmm.tsv'
set multiplot title "C5: AIC / BIC path of the GMM fits (low entries = level 1)"
tex = "erosion marble cloud"
# K of the rows of texture t, low entries = level 1, cutoff rule `rule`; NaN elsewhere
sel(t, rule) = strcol("texture") eq t && column("low_levels") == 1 && strcol("cutoff_rule") eq rule ? column("K") : NaN
# a paper_* value of texture t in gmm.tsv (the literal-cutoff row)
paper(t, name) = strcol("texture") eq t && column("low_levels") == 1 && strcol("cutoff_rule") eq "thesis" ? column(name) : NaN
set grid
set xlabel "K (components)"
set format y "%.1s%c"
unset key
do for [i=1:3] {
  t = word(tex, i)
  stats g using (paper(t, "paper_K_initial")) nooutput
  k0 = STATS_max
  stats g using (paper(t, "paper_K_final")) nooutput
  k1 = STATS_max
  stats g using (paper(t, "paper_AIC")) nooutput
  aic = STATS_max
  set title sprintf("%s\nthesis: K %g -> %g, AIC %.3g", t, k0, k1, aic)
  set origin (i - 1) / 3.0, 0.1
  set size 1 / 3.0, 0.86
  set xrange [0:k1 + 4]
  set arrow 1 from k0, graph 0 to k0, graph 1 nohead dt 2 lw 1.5 lc rgb "gray40"
  set arrow 2 from k1, graph 0 to k1, graph 1 nohead dt 3 lw 1.5 lc rgb "black"
  plot f using (sel(t, "thesis")):"AIC" with linespoints pt 7 ps 0.6 lc rgb "blue" title "AIC, thesis cutoff", \
       f using (sel(t, "thesis")):"BIC" with linespoints pt 6 ps 0.6 dt 2 lc rgb "blue" title "BIC, thesis cutoff", \
       f using (sel(t, "matched_K0")):"AIC" with linespoints pt 5 ps 0.8 lc rgb "red" title "AIC, matched K0", \
       f using (sel(t, "matched_K0")):"BIC" with linespoints pt 4 ps 0.8 dt 2 lc rgb "red" title "BIC, matched K0"
}
# One key for the three panels, in a strip of its own under them (it covers no data).
set origin 0, 0
set size 1, 0.1
unset arrow
unset title
unset xlabel
unset border
unset tics
unset grid
set xrange [0:1]
set yrange [0:1]
set key center center horizontal maxrows 2 font ",9" samplen 2
plot NaN with linespoints pt 7 ps 0.6 lc rgb "blue" title "AIC, thesis cutoff", \
     NaN with linespoints pt 6 ps 0.6 dt 2 lc rgb "blue" title "BIC, thesis cutoff", \
     NaN with linespoints pt 5 ps 0.8 lc rgb "red" title "AIC, matched K0", \
     NaN with linespoints pt 4 ps 0.8 dt 2 lc rgb "red" title "BIC, matched K0", \
     NaN with lines dt 2 lw 1.5 lc rgb "gray40" title "thesis initial K", \
     NaN with lines dt 3 lw 1.5 lc rgb "black" title "thesis final K"
unset multiplot

# C5 (sec. 3.5.3): AIC against the number of mixture components along the
# selection path (pool replicate 0), per texture: the headline reading of
# readings.tsv (aic_readings.tsv rows with headline = 1), the reading selected
# by its matches to the thesis (best_match = 1) and C6's reading (1000-row
# subsample, (cos, sin) chords, cutoff matched to the thesis's initial K). The thesis's initial and final K and its
# AIC (Tables 4.2-4.4, gmm.tsv's paper_* columns) are drawn as lines.
# Called as: gnuplot -e "dir='results/c5_pools'" THIS
set terminal pngcairo size 900,640 font "DejaVu Sans,10"
set output dir.'/aic.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name: texture, low_levels, cutoff_rule, K, AIC, BIC, ...
f = dir.'/aic_readings.tsv'
g = dir.'/gmm.tsv'
set multiplot title "C5: AIC path of the GMM fits (headline, best match, C6's reading) against the thesis"
tex = "erosion marble cloud"
# K of the rows of texture t on the headline reading (h = 1) or on reading id; NaN elsewhere
hsel(t) = strcol("texture") eq t && column("headline") == 1 ? column("K") : NaN
bsel(t) = strcol("texture") eq t && column("best_match") == 1 ? column("K") : NaN
rsel(t, id) = strcol("texture") eq t && strcol("reading") eq id ? column("K") : NaN
alt = "sub1000/cossin/successive/matched_K0"
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
  stats f using (hsel(t)) nooutput
  kmax = STATS_max > k1 ? STATS_max : k1
  stats f using (bsel(t)) nooutput
  kmax = STATS_max > kmax ? STATS_max : kmax
  set title sprintf("%s\nthesis: K %g -> %g, AIC %.3g", t, k0, k1, aic)
  set origin (i - 1) / 3.0, 0.1
  set size 1 / 3.0, 0.86
  set xrange [0:kmax + 4]
  set arrow 1 from k0, graph 0 to k0, graph 1 nohead dt 2 lw 1.5 lc rgb "gray40"
  set arrow 2 from k1, graph 0 to k1, graph 1 nohead dt 3 lw 1.5 lc rgb "black"
  plot f using (hsel(t)):"AIC" with linespoints pt 7 ps 0.6 lc rgb "blue" title "AIC, headline reading", \
       f using (bsel(t)):"AIC" with linespoints pt 9 ps 0.6 lc rgb "orange" title "best match", \
       f using (rsel(t, alt)):"AIC" with linespoints pt 5 ps 0.8 lc rgb "red" title "AIC, C6's reading", \
       aic with lines dt 4 lw 1.5 lc rgb "dark-green" title "thesis AIC"
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
plot NaN with linespoints pt 7 ps 0.6 lc rgb "blue" title "AIC, headline reading of readings.tsv", \
     NaN with linespoints pt 9 ps 0.6 lc rgb "orange" title "AIC, reading selected by its matches", \
     NaN with linespoints pt 5 ps 0.8 lc rgb "red" title "AIC, C6's reading (sub1000, cos/sin, matched K0)", \
     NaN with lines dt 4 lw 1.5 lc rgb "dark-green" title "thesis AIC", \
     NaN with lines dt 2 lw 1.5 lc rgb "gray40" title "thesis initial K", \
     NaN with lines dt 3 lw 1.5 lc rgb "black" title "thesis final K"
unset multiplot

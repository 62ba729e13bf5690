# C5 (sec. 3.5.3): AIC and BIC against the number of mixture components along
# the selection path (first seed), per texture, for the literal thesis cutoff
# (path from K = 1) and the cutoff matched to the thesis's initial K.
# Called as: gnuplot -e "dir='results/c5_pools'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,10"
set output dir.'/aic.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name: texture, low_levels, cutoff_rule, K, AIC, BIC, ...
f = dir.'/aic_path.tsv'
set multiplot layout 1,3 title "C5: AIC / BIC path of the GMM fits (low entries = level 1)"
tex = "erosion marble cloud"
k0 = "30 39 20"
# K of the rows of texture t, low entries = level 1, cutoff rule `rule`; NaN elsewhere
sel(t, rule) = strcol("texture") eq t && column("low_levels") == 1 && strcol("cutoff_rule") eq rule ? column("K") : NaN
set grid
set xlabel "K (components)"
set format y "%.1s%c"
do for [i=1:3] {
  t = word(tex, i)
  set title t." (thesis K0 = ".word(k0, i).")"
  set key bottom left font ",8"
  plot f using (sel(t, "thesis")):"AIC" with linespoints pt 7 ps 0.6 lc rgb "blue" title "AIC, thesis cutoff", \
       f using (sel(t, "thesis")):"BIC" with linespoints pt 6 ps 0.6 dt 2 lc rgb "blue" title "BIC, thesis cutoff", \
       f using (sel(t, "matched_K0")):"AIC" with linespoints pt 5 ps 0.8 lc rgb "red" title "AIC, matched K0", \
       f using (sel(t, "matched_K0")):"BIC" with linespoints pt 4 ps 0.8 dt 2 lc rgb "red" title "BIC, matched K0"
}
unset multiplot

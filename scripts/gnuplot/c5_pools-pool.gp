# C5 (sec. 3.5.1-3.5.2): E_R (eq. 3.18) of each pool run at its random start
# and at its best, per texture; the original table's E_R as a line.
# Called as: gnuplot -e "dir='results/c5_pools'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,10"
set output dir.'/pool.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name (pool_runs.tsv, original.tsv)
f = dir.'/pool_runs.tsv'
o = dir.'/original.tsv'
set multiplot layout 1,3 title "C5: E_R of the pool runs (low entries = level 1)"
tex = "erosion marble cloud"
set grid
set xlabel "run q"
set logscale y
do for [i=1:3] {
  t = word(tex, i)
  stats o using (strcol("texture") eq t && column("low_levels") == 1 ? column("E_R_original") : NaN) nooutput
  eo = STATS_max
  set title t
  set key top right font ",8"
  plot f using (strcol("texture") eq t && column("low_levels") == 1 ? column("run") : NaN):"E_start" with points pt 6 ps 0.5 lc rgb "gray50" title "random start", \
       f using (strcol("texture") eq t && column("low_levels") == 1 ? column("run") : NaN):"E_best" with points pt 7 ps 0.5 lc rgb "blue" title "best", \
       eo with lines lw 2 lc rgb "red" title "original table"
}
unset multiplot

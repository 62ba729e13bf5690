# The plot of a parameter sweep, drawn by `scripts/noiselab sweep merge`.
# Variables (set with -e by the merge, from build/tools/noiselab-sweep):
#   dat      plot.dat: one block per legend entry, "x \"title\" spread" then
#            x, mean over seeds, sd over seeds; blocks ny1..nblocks-1 belong
#            to the second column (right axis)
#   out, title, xlabel, ylabel, y2label, logx, ny1, nblocks
# Columns by name ("x", "spread"); the mean's header is the block's legend
# entry (tools/sweep.c writes it so), so it alone is taken as column 2.
set terminal pngcairo size 960,600 font 'DejaVu Sans,10'
set output out
set datafile separator "\t"
set datafile columnheaders
set title title noenhanced
set xlabel xlabel noenhanced
set ylabel ylabel noenhanced
set key outside right top noenhanced
set grid
if (logx) { set logscale x; set format x "10^{%T}" }
set bars small
# gnuplot's default cycle has 8 colours, so a sweep of 10 values drew two
# pairs alike: 20 distinct colours (Tableau's 10 and their light pairs,
# alternating) and a point shape per series, so that series i and i + 20
# still differ by shape.
array C[20] = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", \
               "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#aec7e8", "#ffbb78", \
               "#98df8a", "#ff9896", "#c5b0d5", "#c49c94", "#f7b6d2", "#c7c7c7", \
               "#dbdb8d", "#9edae5"]
col(i) = C[i % 20 + 1]
shape(i) = i % 13 + 1
if (nblocks > ny1) {
  set y2label y2label noenhanced
  set ytics nomirror
  set y2tics
  plot for [i=0:ny1-1] dat index i using "x":2:"spread" with yerrorlines lw 1.5 \
         lc rgb col(i) pt shape(i) title columnheader(2), \
       for [i=ny1:nblocks-1] dat index i using "x":2:"spread" axes x1y2 with yerrorlines dt 2 \
         lw 1.5 lc rgb col(i) pt shape(i) title columnheader(2)
} else {
  plot for [i=0:ny1-1] dat index i using "x":2:"spread" with yerrorlines lw 1.5 \
         lc rgb col(i) pt shape(i) title columnheader(2)
}

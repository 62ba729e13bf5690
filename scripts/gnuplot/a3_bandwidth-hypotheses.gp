# A3: F_sup of each reading of the method (hypotheses.tsv), mean +- 2 sd over
# seeds, against the paper's Table 5.2 value, one panel per signal.
# Called as: gnuplot -e "dir='results/a3_bandwidth'" THIS
set terminal pngcairo size 1100,500 font "DejaVu Sans,9"
set output dir.'/hypotheses.png'
set datafile separator "\t"
set datafile columnheaders
f = dir.'/hypotheses.tsv'
set multiplot layout 1,3 title "F_{sup} by reading (mean +- 2 sd over seeds); dashed: the paper"
set grid y
set xtics rotate by 60 right noenhanced
set offsets 0.5, 0.5, 0, 0
set ylabel "F_{sup} (cycles per unit; radians for 'radians')"
set logscale y
set yrange [0.5:16]
set key top left
do for [k = 0:2] {
  set title (k == 0 ? "1st octave" : k == 1 ? "2nd octave" : "Fnoise_2")
  # rows come as (reading, signal), signals in this order: every 3::k; x = the reading's index
  plot f every 3::k using 0:"f_sup":(2 * column("f_sup_sd")):xtic(strcol("hypothesis")) \
         with yerrorbars pt 7 title "ours", \
       f every 3::k using 0:"paper_f_sup" with lines dt 2 lw 2 title "paper"
}
unset multiplot

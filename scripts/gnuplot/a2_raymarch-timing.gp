# A2 (Table 5.1): speed-up of incremental bounding against the number of
# octaves: the paper's GPU time ratios, our noise-evaluation ratio at the
# fitted reading (the run's parameters, fit.tsv) and at a = alt_slope, and
# our CPU time ratio.
# Called as: gnuplot -e "dir='results/a2_raymarch'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/timing.png'
set datafile separator "\t"
set datafile columnheaders
f = dir.'/timing.tsv'
set key top left
set grid
set logscale y
set xlabel "octaves N (terms 0..N)"
set ylabel "plain / bounded"
set title "Incremental bounding: speed-up against the number of octaves"
plot f using "octaves":"paper_ratio" with linespoints lw 2 dt 2 title "paper (GPU): time ratio", \
     f using "octaves":"eval_ratio":"eval_ratio_sd" with yerrorlines lw 2 title "ours, fitted reading: noise-evaluation ratio", \
     f using "octaves":"alt_eval_ratio":"alt_eval_ratio_sd" with yerrorlines lw 2 title "ours, a = -4: noise-evaluation ratio", \
     f using "octaves":"ratio" with linespoints lw 1 title "ours, fitted reading: CPU time ratio"

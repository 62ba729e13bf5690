# A2 (Table 5.1): speed-up of incremental bounding, ours (time and noise
# evaluations) against the paper's GPU times.
# Called as: gnuplot -e "dir='results/a2_raymarch'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/timing.png'
set datafile separator "\t"
set datafile columnheaders
f = dir.'/timing.tsv'
set key top left
set grid
set xlabel "octaves N (terms 0..N)"
set ylabel "plain / bounded"
set title "Incremental bounding: speed-up against the number of octaves"
plot f using "octaves":"ratio" with linespoints lw 2 title "ours: time ratio", \
     f using "octaves":"eval_ratio" with linespoints lw 2 title "ours: noise-evaluation ratio", \
     f using "octaves":"paper_ratio" with linespoints lw 2 dt 2 title "paper (GPU): time ratio"

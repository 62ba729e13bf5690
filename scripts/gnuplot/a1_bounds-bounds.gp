# A1: largest |Fnoise_n| seen on random points against the paper's bound
# S_{n-1} (|noise| <= 1) and the analytic bound of improved noise.
# Called as: gnuplot -e "dir='results/a1_bounds'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/bounds.png'
set datafile separator "\t"
set datafile columnheaders
set key bottom right
set grid
set xlabel "octaves n"
set ylabel "|Fnoise_n|"
set yrange [0:2.6]
set title "Fractal bound (eq. 4.2) against the largest value seen"
f = dir.'/bounds.tsv'
plot f using "octaves":"S" with linespoints lw 2 title "paper: S_{n-1} (|noise| <= 1)", \
     f using "octaves":"bound" with linespoints lw 2 title "1.2247 S_{n-1} (analytic bound)", \
     f using "octaves":"max_abs_mean":"max_abs_sd" with yerrorlines lw 2 title "max |Fnoise_n| seen (mean +- sd over seeds)", \
     f using "octaves":"max_abs" with points pt 7 title "max over all seeds"

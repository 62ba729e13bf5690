# S1: radially averaged power spectrum of the fractal sum, one curve per
# octave count. Called as: gnuplot -e "dir='results/s1_fractal_sum'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/fractal_spectrum.png'
set datafile separator "\t"
set logscale xy
set format y "10^{%L}"
set xlabel "frequency (cycles per unit)"
set ylabel "power"
set key top right
set grid
set title "Fractal sum: radially averaged power spectrum (mean over seeds)"
f = dir.'/fractal_spectrum.tsv'
plot for [c=2:5] f using 1:c with lines lw 2 title columnheader(c)

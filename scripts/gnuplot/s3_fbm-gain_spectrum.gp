# S3: radially averaged power spectrum of fBm, one curve per
# gain. Called as: gnuplot -e "dir='results/s3_fbm'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output dir.'/gain_spectrum.png'
set datafile separator "\t"
set datafile columnheaders
set logscale xy
set format y "10^{%L}"
set xlabel "frequency (cycles per unit)"
set ylabel "power"
set key top right
set grid
set title "fBm, varying gain: radially averaged power spectrum (mean over seeds)"
f = dir.'/gain_spectrum.tsv'
# One curve per column other than "freq", addressed by its header name.
ys = system("head -1 '".f."' | tr '\\t' '\\n' | grep -vx freq | sed 's/.*/\"&\"/' | tr '\\n' ' '")
plot for [i=1:words(ys)] f using "freq":(column(word(ys, i))) with lines lw 2 title word(ys, i)

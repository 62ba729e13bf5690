# A3 (Fig. 5.5): one-sided PSD of the 1D signals and their tail energy
# Gamma(lambda), with the threshold T = (2/255)^2.
# Called as: gnuplot -e "dir='results/a3_bandwidth'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,10"
set output dir.'/psd.png'
set datafile separator "\t"
set datafile columnheaders
f = dir.'/psd.tsv'
T = (2.0/255)**2
set multiplot layout 1,2 title "PSD and Gamma(lambda) = energy at and above lambda"
set logscale y
set format y "10^{%L}"
set xlabel "frequency (cycles per unit)"
set grid
set xrange [0:6]
set ylabel "PSD (per bin)"
set yrange [1e-14:*]
set key top right
plot f using "freq":"psd_oct1" with lines lw 1 title "1st octave", \
     f using "freq":"psd_oct2" with lines lw 1 title "2nd octave", \
     f using "freq":"psd_sum" with lines lw 1 title "Fnoise_2"
set ylabel "Gamma(lambda)"
set yrange [1e-8:1]
plot f using "freq":"gamma_oct1" with lines lw 2 title "1st octave", \
     f using "freq":"gamma_oct2" with lines lw 2 title "2nd octave", \
     f using "freq":"gamma_sum" with lines lw 2 title "Fnoise_2", \
     T with lines dt 2 lc rgb "black" title "T = (2/255)^2"
unset multiplot

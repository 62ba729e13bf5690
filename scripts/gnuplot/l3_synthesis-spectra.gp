# Radially averaged power spectra (luminance) of exemplar and synthesis,
# one panel per procedural exemplar.
set terminal pngcairo size 900,600
set output dir.'/spectra.png'
set datafile separator "\t"
set datafile columnheaders
set multiplot layout 2,2
set logscale xy
set format y '10^{%L}'
set xrange [*:0.5]
set key bottom left font ',8'
set xlabel 'cycles per pixel' font ',9'
set ylabel 'power' font ',9'
do for [k in "wavelet clouds granite marble"] {
  set title k
  plot dir.'/spectrum_'.k.'.tsv' using "freq":(column("exemplar") > 0 ? column("exemplar") : 1/0) with lines lw 2 title 'exemplar', \
       '' using "freq":(column("synthesis") > 0 ? column("synthesis") : 1/0) with lines lw 1.5 title 'synthesis', \
       '' using "freq":(column("synthesis_nohist") > 0 ? column("synthesis_nohist") : 1/0) with lines lw 1 dt 2 title 'no histogram matching'
}
unset multiplot

# Radially averaged power spectra (luminance) of exemplar and synthesis,
# one panel per procedural exemplar.
set terminal pngcairo size 900,600
set output dir.'/spectra.png'
set datafile separator "\t"
set multiplot layout 2,2
set logscale xy
set format y '10^{%L}'
set xrange [*:0.5]
set key bottom left font ',8'
set xlabel 'cycles per pixel' font ',9'
set ylabel 'power' font ',9'
do for [k in "wavelet clouds granite marble"] {
  set title k
  plot dir.'/spectrum_'.k.'.tsv' every ::1 using 1:($2 > 0 ? $2 : 1/0) with lines lw 2 title 'exemplar', \
       '' every ::1 using 1:($3 > 0 ? $3 : 1/0) with lines lw 1.5 title 'synthesis', \
       '' every ::1 using 1:($4 > 0 ? $4 : 1/0) with lines lw 1 dt 2 title 'no histogram matching'
}
unset multiplot

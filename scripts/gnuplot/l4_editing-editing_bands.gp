# Frequency-based editing: luminance band power of the edited synthesis over
# the original, against the requested attenuation (factor^2).
set terminal pngcairo size 900,600
set output dir.'/editing_bands.png'
set datafile separator "\t"
set datafile columnheaders
set logscale y
set xlabel 'band k (0 = finest)'
set ylabel 'power ratio, edited / original'
set key bottom right
set xtics 1
plot dir.'/editing.tsv' using "band":"ratio" with linespoints lw 2 pt 7 title 'measured (luminance)', \
     '' using "band":"ratio_nohist" with linespoints lw 2 pt 5 title 'measured, no histogram matching', \
     '' using "band":"expected" with lines lw 1 dt 2 lc rgb 'black' title 'requested'

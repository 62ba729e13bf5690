# Frequency-based editing: luminance band power of the edited synthesis over
# the original, against the requested attenuation (factor^2).
set terminal pngcairo size 900,600
set output dir.'/editing_bands.png'
set datafile separator "\t"
set logscale y
set xlabel 'band k (0 = finest)'
set ylabel 'power ratio, edited / original'
set key bottom right
set xtics 1
plot dir.'/editing.tsv' every ::1 using 1:4 with linespoints lw 2 pt 7 title 'measured (luminance)', \
     '' every ::1 using 1:5 with linespoints lw 2 pt 5 title 'measured, no histogram matching', \
     '' every ::1 using 1:6 with lines lw 1 dt 2 lc rgb 'black' title 'requested'

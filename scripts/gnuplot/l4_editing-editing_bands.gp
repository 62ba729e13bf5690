# Frequency-based editing: luminance band power of the edited synthesis over
# the original (mean and sd over seeds), against the requested attenuation
# (factor^2) and against floor + factor^2 (1 - floor), the floor being what
# is left with the bands removed.
set terminal pngcairo size 900,600
set output dir.'/editing_bands.png'
set datafile separator "\t"
set datafile columnheaders
set logscale y
set xlabel 'band k (0 = finest)'
set ylabel 'power ratio, edited / original'
set key bottom right
set xtics 1
plot dir.'/editing.tsv' using "band":"ratio":"ratio_sd" with yerrorlines lw 2 pt 7 title 'measured (luminance)', \
     '' using "band":"ratio_nohist":"ratio_nohist_sd" with yerrorlines lw 2 pt 5 title 'measured, no histogram matching', \
     '' using "band":"floor" with linespoints lw 1 pt 6 title 'floor (bands removed)', \
     '' using "band":"predicted" with lines lw 1 dt 3 lc rgb 'gray30' title 'floor + factor^2 (1 - floor)', \
     '' using "band":"expected" with lines lw 1 dt 2 lc rgb 'black' title 'requested'

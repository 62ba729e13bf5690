# Relative RMS weight error against image size, mean +- sd over seeds.
set terminal pngcairo size 900,600
set output dir.'/error.png'
set datafile separator "\t"
set datafile columnheaders
set logscale x 2
set xlabel 'image size (pixels per side)'
set ylabel 'relative RMS weight error |w_{est} - w| / |w|'
set yrange [0:*]
set key top right
plot dir.'/error_vs_size.tsv' using "size":"err_mean":"err_sd" with yerrorlines lw 2 pt 7 title 'all bands (random weights in [0.1, 1])', \
     '' using "size":"err_fine_mean":"err_fine_sd" with yerrorlines lw 2 pt 5 title '6 finest bands'

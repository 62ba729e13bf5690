# Relative RMS weight error against image size, mean +- sd over seeds.
set terminal pngcairo size 900,600
set output dir.'/error.png'
set datafile separator "\t"
set logscale x 2
set xlabel 'image size (pixels per side)'
set ylabel 'relative RMS weight error |w_{est} - w| / |w|'
set yrange [0:*]
set key top right
plot dir.'/error_vs_size.tsv' every ::1 using 1:3:4 with yerrorlines lw 2 pt 7 title 'all bands (random weights in [0.1, 1])', \
     '' every ::1 using 1:5:6 with yerrorlines lw 2 pt 5 title '6 finest bands'

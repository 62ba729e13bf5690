# RMS weight error per band at the sweep's largest size, per estimator (bands.tsv).
set terminal pngcairo size 900,600
set output dir.'/bands.png'
set datafile separator "\t"
set datafile columnheaders
f = dir.'/bands.tsv'
stats f using "size" nooutput
big = STATS_max
est(name) = (strcol("estimator") eq name && column("size") == big) ? column("rmse") : NaN
set xlabel sprintf('band k (0 = finest) at %d x %d pixels', big, big)
set ylabel 'RMS weight error over seeds'
set yrange [0:*]
set key top left
plot f using "band":(est("eq12")) with linespoints lw 2 pt 7 title 'eq. 12 (paper)', \
     f using "band":(est("eq12_taper")) with linespoints lw 2 pt 5 title 'eq. 12, tapered DFT', \
     f using "band":(est("nnls_raw")) with linespoints lw 2 pt 9 title 'transfer matrix + NNLS, raw DFT', \
     f using "band":(est("corrected")) with linespoints lw 2 pt 11 title 'corrected (matrix + taper + NNLS)'

# Fig. 4 (a, c): true and estimated weights per band, as grouped bars.
set terminal pngcairo size 900,600
set output dir.'/weights.png'
set datafile separator "\t"
set datafile columnheaders
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set xlabel 'band k (0 = finest, 1/4..1/2 cycles per pixel)'
set ylabel 'weight'
set yrange [0:*]
set key top left
plot dir.'/weights.tsv' using "true":xtic(strcol("band")) title 'true (a)', '' using "est" title 'eq. 12 from (b): (c)', '' using "est_of_d" title 'eq. 12 from (d)', '' using "corrected" title 'corrected, from (b)'

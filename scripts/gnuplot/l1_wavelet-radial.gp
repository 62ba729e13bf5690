# Radially averaged power of one wavelet-noise band (2D, 3D slice), with the
# band's octave from edges.tsv.
set terminal pngcairo size 900,600
set output dir.'/radial.png'
set datafile separator "\t"
stats dir.'/edges.tsv' using 1 every ::1 nooutput name 'LO'
stats dir.'/edges.tsv' using 2 every ::1 nooutput name 'HI'
set logscale xy
set xlabel 'frequency (cycles per pixel)'
set ylabel 'mean power'
set key top right
set xrange [*:0.5]
set arrow from LO_min, graph 0 to LO_min, graph 1 nohead dt 2 lc rgb 'gray40'
set arrow from HI_min, graph 0 to HI_min, graph 1 nohead dt 2 lc rgb 'gray40'
plot dir.'/radial.tsv' every ::1 using 1:($2 > 0 ? $2 : 1/0) with lines lw 2 title '2D wavelet noise', \
     '' every ::1 using 1:($3 > 0 ? $3 : 1/0) with lines lw 2 title 'slice of 3D wavelet noise'

# Radially averaged power of one wavelet-noise band (2D, 3D slice), with the
# band's octave from edges.tsv.
set terminal pngcairo size 900,600
set output dir.'/radial.png'
set datafile separator "\t"
set datafile columnheaders
stats dir.'/edges.tsv' using "lo" nooutput name 'LO'
stats dir.'/edges.tsv' using "hi" nooutput name 'HI'
set logscale xy
set xlabel 'frequency (cycles per pixel)'
set ylabel 'mean power'
set key top right
set xrange [*:0.5]
set arrow from LO_min, graph 0 to LO_min, graph 1 nohead dt 2 lc rgb 'gray40'
set arrow from HI_min, graph 0 to HI_min, graph 1 nohead dt 2 lc rgb 'gray40'
plot dir.'/radial.tsv' using "freq":(column("power2d") > 0 ? column("power2d") : 1/0) with lines lw 2 title '2D wavelet noise', \
     '' using "freq":(column("power3d") > 0 ? column("power3d") : 1/0) with lines lw 2 title 'slice of 3D wavelet noise'

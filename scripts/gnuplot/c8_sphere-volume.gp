# C8: the 3D pattern and the optimised noise as voxel clouds (torus, first
# seed): left the voxels inside the pattern (D >= 1/2), right the voxels where
# the optimised control value c is among the highest fraction equal to the
# pattern's volume fraction (the iso-surface of c enclosing the same volume),
# coloured by height z.
# Called as: gnuplot -e "dir='results/c8_sphere'" THIS
set terminal pngcairo size 1000,480 font "DejaVu Sans,10"
set output dir.'/volume.png'
set datafile separator "\t"
set datafile columnheaders   # voxels.tsv: x, y, z, D, c, in_pattern, top_c
f = dir.'/voxels.tsv'
set multiplot layout 1,2 title "C8: torus pattern and the optimised 3D noise's matching iso-volume (first seed)"
set view 60, 30
set xrange [0:1]; set yrange [0:1]; set zrange [0:1]
set xlabel "x"; set ylabel "y"; set zlabel "z"
set ticslevel 0
set palette rgbformulae 33,13,10
unset colorbox
unset key
set title "pattern: D >= 1/2"
splot f using "x":"y":(column("in_pattern") > 0 ? column("z") : NaN):"z" with points pt 7 ps 0.5 lc palette
set title "optimised c: top voxels (same volume)"
splot f using "x":"y":(column("top_c") > 0 ? column("z") : NaN):"z" with points pt 7 ps 0.5 lc palette
unset multiplot

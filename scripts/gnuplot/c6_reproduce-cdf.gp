# C6 (Fig 4.10, 4.12, 4.14): ECDF of the 512 gradient angles of the original
# optimised table and of 8 reproductions (top), and their deviation from the
# ideal uniform CDF (bottom), per texture.
# Called as: gnuplot -e "dir='results/c6_reproduce'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,10"
set output dir.'/cdf.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name: F, u_original, u_r1 .. u_r8
set multiplot layout 2,3 title "C6: CDF of the gradient angles, original (red) and 8 reproductions (gray)"
tex = "erosion marble cloud"
set grid
do for [i=1:3] {
  f = dir.'/cdf_'.word(tex, i).'.tsv'
  set title word(tex, i)
  set xlabel "angle / 2 pi"
  set ylabel "F"
  set xrange [0:1]
  set yrange [0:1]
  set key top left font ",8"
  plot for [j=1:8] f using (column("u_r".j)):"F" with steps lc rgb "gray60" notitle, \
       f using "u_original":"F" with steps lw 2 lc rgb "red" title "original", \
       x with lines dt 2 lc rgb "black" title "ideal"
}
do for [i=1:3] {
  f = dir.'/cdf_'.word(tex, i).'.tsv'
  set title word(tex, i).": F - ideal"
  set ylabel "deviation"
  set autoscale y
  set key top right font ",8"
  plot for [j=1:8] f using (column("u_r".j)):(column("F") - column("u_r".j)) with steps lc rgb "gray60" notitle, \
       f using "u_original":(column("F") - column("u_original")) with steps lw 2 lc rgb "red" title "original", \
       0 with lines dt 2 lc rgb "black" notitle
}
unset multiplot

# C2 (Fig 4.5, 4.6 left): the ECDF of the optimised angles per objective
# against the ideal uniform line, drawn as the deviation F_obs - F_ideal (the
# ECDFs themselves lie within 0.01 of the diagonal and of each other: as
# curves they overlap). One panel per pattern; the key in a strip below.
# Called as: gnuplot -e "dir='results/c2_ks_vs_chisq'" THIS
set terminal pngcairo size 900,480 font "DejaVu Sans,10"
set output dir.'/cdf.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name: cdf_PATTERN.tsv is F, u_ks, u_chisq, u_kuiper
set multiplot title "C2: ECDF of the 512 optimised gradient angles minus the ideal uniform CDF (first seed)"
pats = "flower x"
unset key
set grid
do for [i=1:2] {
  p = word(pats, i)
  f = dir.'/cdf_'.p.'.tsv'
  set origin (i - 1) / 2.0, 0.1
  set size 0.5, 0.82
  set title p." pattern" noenhanced
  set xlabel "angle / 2 pi"
  set ylabel "F_{obs} - F_{ideal}"
  set xrange [0:1]
  plot 0 with lines lc rgb "#ff69b4" lw 2, \
       f using "u_ks":(column("F") - column("u_ks")) with steps lw 1.5 lc rgb "blue", \
       f using "u_chisq":(column("F") - column("u_chisq")) with steps lw 1.5 lc rgb "red", \
       f using "u_kuiper":(column("F") - column("u_kuiper")) with steps lw 1.5 lc rgb "dark-green"
}
set origin 0, 0
set size 1, 0.1
unset title; unset xlabel; unset ylabel; unset border; unset tics; unset grid
set xrange [0:1]; set yrange [0:1]
set key center center horizontal font ",9" samplen 2
plot NaN with lines lw 2 lc rgb "#ff69b4" title "ideal", \
     NaN with steps lw 1.5 lc rgb "blue" title "KS term", \
     NaN with steps lw 1.5 lc rgb "red" title "chi-square term", \
     NaN with steps lw 1.5 lc rgb "dark-green" title "Kuiper term"
unset multiplot

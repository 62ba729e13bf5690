# C2 (Fig 4.5, 4.6 left): ECDF of the optimised angles per objective against
# the ideal uniform line (top), and the deviation F_obs - F_ideal (bottom).
# Called as: gnuplot -e "dir='results/c2_ks_vs_chisq'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,10"
set output dir.'/cdf.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name: cdf_PATTERN.tsv is F, u_ks, u_chisq, u_kuiper
set multiplot layout 2,2 title "C2: CDF of the 512 optimised gradient angles (first seed)"
pats = "flower x"
do for [i=1:2] {
  p = word(pats, i)
  f = dir.'/cdf_'.p.'.tsv'
  set title p." pattern: ECDF"
  set xlabel "angle / 2 pi"
  set ylabel "F"
  set key top left
  set xrange [0:1]
  set yrange [0:1]
  plot x with lines lw 2 lc rgb "#ff69b4" title "ideal", \
       f using "u_ks":"F" with steps lw 1.5 lc rgb "blue" title "KS term", \
       f using "u_chisq":"F" with steps lw 1.5 lc rgb "red" title "chi-square term", \
       f using "u_kuiper":"F" with steps lw 1.5 lc rgb "dark-green" title "Kuiper term"
}
do for [i=1:2] {
  p = word(pats, i)
  f = dir.'/cdf_'.p.'.tsv'
  set title p." pattern: F_obs - F_ideal" noenhanced
  set xlabel "angle / 2 pi"
  set ylabel "deviation"
  set key top right
  set xrange [0:1]
  set autoscale y
  plot 0 with lines lc rgb "#ff69b4" notitle, \
       f using "u_ks":(column("F") - column("u_ks")) with steps lw 1.5 lc rgb "blue" title "KS term", \
       f using "u_chisq":(column("F") - column("u_chisq")) with steps lw 1.5 lc rgb "red" title "chi-square term", \
       f using "u_kuiper":(column("F") - column("u_kuiper")) with steps lw 1.5 lc rgb "dark-green" title "Kuiper term"
}
unset multiplot

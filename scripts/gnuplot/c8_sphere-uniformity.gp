# C8: uniformity on the sphere. ECDF minus the uniform CDF of u = (z + 1)/2
# (z = cos polar angle, uniform on [-1, 1] for uniform directions) and of
# u = phi / 2 pi, for the optimised table and its random start (first seed,
# torus). The largest |deviation| of each curve is that margin's KS D.
# Called as: gnuplot -e "dir='results/c8_sphere'" THIS
set terminal pngcairo size 900,460 font "DejaVu Sans,10"
set output dir.'/uniformity.png'
set datafile separator "\t"
set datafile columnheaders   # ecdf.tsv: F, z_opt, phi_opt, z_rand, phi_rand
f = dir.'/ecdf.tsv'
set multiplot layout 1,2 title "C8: ECDF of the M unit gradients' z = cos(polar) and azimuth, minus the uniform CDF"
set grid
set xrange [0:1]
set xlabel "u"
set ylabel "F_{obs}(u) - u"
set key below horizontal maxrows 1 font ",9"   # under the plot: it covers no data
set title "z = cos(polar), u = (z + 1)/2"
plot 0 with lines lc rgb "#ff69b4" lw 2 title "ideal", \
     f using "z_opt":(column("F") - column("z_opt")) with steps lw 1.5 lc rgb "blue" title "optimised", \
     f using "z_rand":(column("F") - column("z_rand")) with steps lw 1.5 lc rgb "gray50" title "random start"
set title "azimuth phi, u = phi / 2 pi"
plot 0 with lines lc rgb "#ff69b4" lw 2 title "ideal", \
     f using "phi_opt":(column("F") - column("phi_opt")) with steps lw 1.5 lc rgb "blue" title "optimised", \
     f using "phi_rand":(column("F") - column("phi_rand")) with steps lw 1.5 lc rgb "gray50" title "random start"
unset multiplot

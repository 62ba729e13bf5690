# C9: per case (texture/pattern), fixed against optimised octave amplitudes:
# E_Con (with the best constant image's, dashed), Pearson r of the control
# value with the pattern, and contrast (sd of the control value); means and
# sd over seeds, and the same optimised within the wide bounds. Rows of
# summary.tsv come in threes: fixed, optimised, optimised_wide.
# Called as: gnuplot -e "dir='results/c9_amplitudes'" THIS
set terminal pngcairo size 1200,460 font "DejaVu Sans,9"
set output dir.'/control.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name (nl_study_cheng_summary_alloc)
s = dir.'/summary.tsv'
fx(a) = strcol("amplitudes") eq "fixed" ? a : NaN
op(a) = strcol("amplitudes") eq "optimised" ? a : NaN
wd(a) = strcol("amplitudes") eq "optimised_wide" ? a : NaN
x0 = -0.2
# one tic per case, from the fixed rows (texture/pattern at x = case index)
tics = system("awk -F'\\t' 'NR==1{for(i=1;i<=NF;i++)c[$i]=i;next} $c[\"amplitudes\"]==\"fixed\"{printf \"%s\\\"%s/%s\\\" %d\", n++ ? \", \" : \"\", $c[\"texture\"], $c[\"pattern\"], n - 1}' '".s."'")
eval "set xtics (".tics.")"
set multiplot layout 1,3 title \
  "C9: fixed vs optimised octave amplitudes, default and wide bounds (mean and sd over seeds)"
set grid ytics
set xtics rotate by -30 left
set offsets 0.5, 0.5, 0, 0
set key below
set style line 1 pt 7 lc rgb "blue"
set style line 2 pt 5 lc rgb "red"
set style line 3 pt 9 lc rgb "dark-green"
k(d) = int(column(0) / 3) + d   # the case index of a row, shifted by d
set ylabel "E_{Con}"
plot s u (fx(k(x0))):"E_con":"E_con_sd" w yerrorbars ls 1 t "fixed", \
     s u (op(k(0))):"E_con":"E_con_sd" w yerrorbars ls 2 t "optimised", \
     s u (wd(k(-x0))):"E_con":"E_con_sd" w yerrorbars ls 3 t "optimised, wide bounds", \
     s u (fx(k(0))):"E_con_const" w points pt 1 ps 2 lc rgb "black" t "best constant"
set ylabel "r with the pattern"
plot s u (fx(k(x0))):"r_pattern":"r_pattern_sd" w yerrorbars ls 1 t "fixed", \
     s u (op(k(0))):"r_pattern":"r_pattern_sd" w yerrorbars ls 2 t "optimised", \
     s u (wd(k(-x0))):"r_pattern":"r_pattern_sd" w yerrorbars ls 3 t "optimised, wide bounds"
set ylabel "contrast (sd of c)"
plot s u (fx(k(x0))):"contrast":"contrast_sd" w yerrorbars ls 1 t "fixed", \
     s u (op(k(0))):"contrast":"contrast_sd" w yerrorbars ls 2 t "optimised", \
     s u (wd(k(-x0))):"contrast":"contrast_sd" w yerrorbars ls 3 t "optimised, wide bounds"
unset multiplot

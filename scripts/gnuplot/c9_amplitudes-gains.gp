# C9: the optimised octave amplitudes 1/a_l = gain / a_thesis (mean and sd
# over seeds of the gain) per case, against the thesis's 1/a_l = 1 / (4 2^(l-1))
# and the bounds [1/R, R] x the thesis's (column R): the default bounds
# (rows "optimised", solid) and the wide ones ("optimised_wide", dashed).
# Called as: gnuplot -e "dir='results/c9_amplitudes'" THIS
set terminal pngcairo size 800,520 font "DejaVu Sans,10"
set output dir.'/gains.png'
set datafile separator "\t"
set datafile columnheaders   # columns by name (nl_study_cheng_gains_alloc)
g = dir.'/gains.tsv'
cases = system("awk -F'\\t' 'NR==1{for(i=1;i<=NF;i++)c[$i]=i;next} !s[$c[\"texture\"]\"/\"$c[\"pattern\"]]++{printf \"%s/%s \", $c[\"texture\"], $c[\"pattern\"]}' '".g."'")
n = words(cases)
set logscale y 2
set xlabel "octave l"
set ylabel "amplitude 1/a_l"
set xtics 1
set grid
set key outside right
set title "C9: optimised octave amplitudes, default bounds (solid) and wide (dashed); mean and sd over seeds"
is(c) = (strcol("texture")."/".strcol("pattern")) eq c && strcol("amplitudes") eq "optimised"
isw(c) = (strcol("texture")."/".strcol("pattern")) eq c && strcol("amplitudes") eq "optimised_wide"
plot g using (is(word(cases, 1)) ? column("octave") : NaN):(1 / column("a_thesis")) with linespoints lw 3 lc rgb "black" pt 4 title "thesis 1/a_l", \
     g using (is(word(cases, 1)) ? column("octave") : NaN):(column("R") / column("a_thesis")) with lines dt 2 lc rgb "gray40" title "bounds", \
     g using (is(word(cases, 1)) ? column("octave") : NaN):(1 / (column("R") * column("a_thesis"))) with lines dt 2 lc rgb "gray40" notitle, \
     for [i=1:n] g using (is(word(cases, i)) ? column("octave") + 0.04 * (i - (n + 1) / 2.0) : NaN):(column("gain") / column("a_thesis")):(column("gain_sd") / column("a_thesis")) \
       with yerrorlines pt 7 ps 0.7 lc i title word(cases, i), \
     g using (isw(word(cases, 1)) ? column("octave") : NaN):(column("R") / column("a_thesis")) with lines dt 3 lc rgb "gray60" title "wide bounds", \
     g using (isw(word(cases, 1)) ? column("octave") : NaN):(1 / (column("R") * column("a_thesis"))) with lines dt 3 lc rgb "gray60" notitle, \
     for [i=1:n] g using (isw(word(cases, i)) ? column("octave") + 0.04 * (i - (n + 1) / 2.0) : NaN):(column("gain") / column("a_thesis")) \
       with linespoints dt 2 pt 6 ps 0.7 lc i notitle

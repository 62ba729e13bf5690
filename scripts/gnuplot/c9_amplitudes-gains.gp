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
set title "C9: optimised octave amplitudes, default bounds (solid) and wide (dashed)"
case(c) = (strcol("texture")."/".strcol("pattern")) eq c
is(c) = case(c) && strcol("amplitudes") eq "optimised"
isw(c) = case(c) && strcol("amplitudes") eq "optimised_wide"
x(ok) = ok ? column("octave") : NaN                   # the octave on rows that pass
xi(ok, i) = ok ? column("octave") + 0.04 * (i - (n + 1) / 2.0) : NaN   # spread per case
amp(v) = v / column("a_thesis")                      # a gain as the amplitude 1/a_l
plot g u (x(is(word(cases, 1)))):(amp(1)) w linespoints lw 3 lc rgb "black" pt 4 \
       t "thesis 1/a_l", \
     g u (x(is(word(cases, 1)))):(amp(column("R"))) w lines dt 2 lc rgb "gray40" t "bounds", \
     g u (x(is(word(cases, 1)))):(amp(1 / column("R"))) w lines dt 2 lc rgb "gray40" notitle, \
     for [i=1:n] g u (xi(is(word(cases, i)), i)):(amp(column("gain"))):(amp(column("gain_sd"))) \
       w yerrorlines pt 7 ps 0.7 lc i t word(cases, i), \
     g u (x(isw(word(cases, 1)))):(amp(column("R"))) w lines dt 3 lc rgb "gray60" \
       t "wide bounds", \
     g u (x(isw(word(cases, 1)))):(amp(1 / column("R"))) w lines dt 3 lc rgb "gray60" notitle, \
     for [i=1:n] g u (xi(isw(word(cases, i)), i)):(amp(column("gain"))) \
       w linespoints dt 2 pt 6 ps 0.7 lc i notitle

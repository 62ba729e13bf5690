# A3: how F_sup and F_inf move with the unstated sample length and rate.
# Called as: gnuplot -e "dir='results/a3_bandwidth'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,10"
set output dir.'/sweep.png'
set datafile separator "\t"
set datafile columnheaders
f = dir.'/sweep.tsv'
set multiplot layout 1,2 title "Bandwidth against sample length (left) and sampling rate (right)"
set logscale x 2
set grid
set key bottom right
set xlabel "length (units)"
set ylabel "frequency (cycles per unit)"
set yrange [0.01:4]
set logscale y
plot f using (strcol("vary") eq "length" ? column("length") : NaN):"oct1_f_sup" with linespoints lw 2 title "1st oct F_{sup}", \
     f using (strcol("vary") eq "length" ? column("length") : NaN):"oct2_f_sup" with linespoints lw 2 title "2nd oct F_{sup}", \
     f using (strcol("vary") eq "length" ? column("length") : NaN):"sum_f_sup" with linespoints lw 2 title "Fnoise_2 F_{sup}", \
     f using (strcol("vary") eq "length" ? column("length") : NaN):"oct1_f_inf" with linespoints dt 2 title "1st oct F_{inf}", \
     f using (strcol("vary") eq "length" ? column("length") : NaN):"oct2_f_inf" with linespoints dt 2 title "2nd oct F_{inf}"
set xlabel "rate (samples per unit)"
plot f using (strcol("vary") eq "rate" ? column("rate") : NaN):"oct1_f_sup" with linespoints lw 2 title "1st oct F_{sup}", \
     f using (strcol("vary") eq "rate" ? column("rate") : NaN):"oct2_f_sup" with linespoints lw 2 title "2nd oct F_{sup}", \
     f using (strcol("vary") eq "rate" ? column("rate") : NaN):"sum_f_sup" with linespoints lw 2 title "Fnoise_2 F_{sup}", \
     f using (strcol("vary") eq "rate" ? column("rate") : NaN):"oct1_f_inf" with linespoints dt 2 title "1st oct F_{inf}", \
     f using (strcol("vary") eq "rate" ? column("rate") : NaN):"oct2_f_inf" with linespoints dt 2 title "2nd oct F_{inf}"
unset multiplot

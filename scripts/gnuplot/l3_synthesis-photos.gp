# Band power ratio synthesis / photo per eq. 13 band (photos.tsv), one panel
# per histogram representation, one line per photograph; filled points are
# the checked bands (share of the photo's power >= min_share), dashed lines
# the x1.3 criterion; lines join the first replicate, points are every
# replicate.
set terminal pngcairo size 1400,420
set output dir.'/photos.png'
set datafile separator "\t"
set datafile columnheaders
f = dir.'/photos.tsv'
ex = system("awk -F'\\t' 'NR > 1 && !seen[$1]++ { printf \"%s \", $1 }' '".f."'")
set multiplot layout 1,3
set logscale y
set yrange [0.1:10]
set xlabel 'eq. 13 band (0 = finest, 0.25-0.5 cycles/pixel)' font ',9'
set ylabel 'power synthesis / photo' font ',9'
set key top left font ',8'
set xtics 1
do for [rep in "gauss33 paper10 calibrated"] {
  set title rep
  plot for [i = 1:words(ex)] f using "band":((strcol("exemplar") eq word(ex, i) && strcol("representation") eq rep && column("replicate") == 0) ? column("ratio") : 1/0) \
         with lines lc i title word(ex, i), \
       for [i = 1:words(ex)] f using "band":((strcol("exemplar") eq word(ex, i) && strcol("representation") eq rep && column("checked") > 0) ? column("ratio") : 1/0) \
         with points pt 7 lc i notitle, \
       1.3 with lines dt 2 lc 'black' notitle, 1/1.3 with lines dt 2 lc 'black' notitle
}
unset multiplot

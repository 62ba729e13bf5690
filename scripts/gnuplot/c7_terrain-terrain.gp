# C7 (Fig 4.15-4.17): per pattern (rows: flower, X, star) the target pattern,
# the height map (the controlled value) and the surface, all over the unit
# square with axes, so the pattern can be found in the terrain.
# Called as: gnuplot -e "dir='results/c7_terrain'" THIS
set terminal pngcairo size 1200,1150 font "DejaVu Sans,9"
set output dir.'/terrain.png'
set datafile separator "\t"
set multiplot layout 3,3 title "C7: terrain from control patterns (height = controlled value c, first seed)"
set palette defined (0 "#1f3f6f", 0.35 "#3f7f3f", 0.6 "#8f7f4f", 0.85 "#9f9f9f", 1 "white")
unset key
pats = "flower x star"
do for [i=1:3] {
  p = word(pats, i)
  # matrix data: $1, $2, $3 are the column index, the row index and the value,
  # not table columns; rows grow downwards in the image (y = row / n).
  # sides from the headers (c0 .. c{n-1})
  n = words(system("head -1 '".dir."/height_".p.".tsv'"))
  g = words(system("head -1 '".dir."/pattern_".p.".tsv'"))
  set view map
  set size ratio -1
  set xrange [0:1]; set yrange [1:0]
  set xlabel "x"; set ylabel "y"
  set xtics 0.25; set ytics 0.25
  unset ztics
  set cbrange [0:1]
  set colorbox
  set title p.": target D"
  splot dir.'/pattern_'.p.'.tsv' matrix skip 1 using (($1 + 0.5) / g):(($2 + 0.5) / g):3 with image
  set cbrange [*:*]
  set title p.": height map"
  splot dir.'/height_'.p.'.tsv' matrix skip 1 using (($1 + 0.5) / n):(($2 + 0.5) / n):3 with image
  unset colorbox
  set view 35, 30, 1, 1.3
  set size noratio
  set yrange [1:0]
  set ztics auto format "%.2f"
  set zlabel "height" rotate
  set pm3d depthorder lighting primary 0.5 specular 0.2
  set xyplane 0
  set title p.": surface"
  splot dir.'/height_'.p.'.tsv' matrix skip 1 using (($1 + 0.5) / n):(($2 + 0.5) / n):3 with pm3d
  unset zlabel
}
unset multiplot

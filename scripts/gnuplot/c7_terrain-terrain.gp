# C7 (Fig 4.15-4.17): terrain from the flower, X and star patterns, the
# controlled value as height, drawn as shaded pm3d surfaces.
# Called as: gnuplot -e "dir='results/c7_terrain'" THIS
set terminal pngcairo size 900,600 font "DejaVu Sans,9"
set output dir.'/terrain.png'
set datafile separator "\t"
set multiplot layout 2,2 title "C7: terrain height maps from control patterns (height = controlled value)"
set view 38, 20, 1.1, 1.3
set pm3d depthorder
set pm3d lighting primary 0.5 specular 0.2
set palette defined (0 "#1f3f6f", 0.35 "#3f7f3f", 0.6 "#8f7f4f", 0.85 "#9f9f9f", 1 "white")
unset colorbox
unset key
unset xtics
unset ytics
set border 16
set ztics 0.2 format "%.1f"
set xyplane 0
pats = "flower x star"
do for [i=1:3] {
  p = word(pats, i)
  set title p." pattern"
  # matrix data: $1, $2, $3 are the x index, the y index and the height, not table columns
  splot dir.'/height_'.p.'.tsv' matrix columnheaders using 1:(-$2):3 with pm3d
}
unset multiplot

#!/usr/bin/env bash
# Quick C7: three height maps (mesh x mesh) with heights in [0, 1] (c = (1 + V)/2
# with V over its analytic bound: a bound check of the kernel). Tables stay
# uniform: E_ks measured 0.0092..0.0115 at --quick over seeds 1..5 (0.0105..0.0114
# at seed 1 on the domain [1, 2]^2); bound 0.02
# (a random table's mean D is 0.87/sqrt(512) = 0.038).
# Controllability: the optimised E_Con is below the unoptimised start's and r
# with the pattern is positive (measured 0.24..0.39 at --quick, seed 1).
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick "${NOIMG[@]}" --threads 2 --out "$out" --patterns "$pat" >/dev/null
# The seed runs are nl_parallel_for items (nl_study_cheng_runs): one thread
# gives the same tables, timing columns aside (the check ignores them).
same_on_one_thread "$exp" "$out" --patterns "$pat"
"$expect" "$out/summary.tsv" rows=3 'E_ks<0.02' 'E_con>0' 'E_con<E_con_random' 'r_pattern>0' \
  'contrast>0' 'contrast<0.5' 'E_con_const>0' image:heightmaps.png
# the target patterns beside the height maps (64 x 64 control grid, D in [0, 1])
for p in flower x star; do "$expect" "$out/pattern_$p.tsv" rows=64 'c0>=0' 'c63<=1'; done
for p in flower x star; do
  "$expect" "$out/height_$p.tsv" rows=48 'c0>=0' 'c0<=1' 'c47>=0' 'c47<=1'
done
# "The height follows the pattern", per pattern: r against 99 random tables
# (Monte-Carlo p in [1/100, 1]; measured r 0.24..0.39 against random tables'
# 0.00 +- 0.07 at --quick, p = 0.01 for all three) and E_Con against the flat
# image (one-sided t over the seeds; E_Con's three parts sum to it).
"$expect" "$out/control.tsv" rows=3 'n_random==99' 'p_random>=0.01' 'p_random<=1' \
  'p_random<=0.05' 'p_flat>=0' 'p_flat<=1' 'r_random_sd>0' 'r_pattern>r_random_mean' \
  'E_con_const>0' 'con_offset_frac>=0' 'con_contrast_frac>=0' 'con_shape_frac>=0' 'mean_D>0' \
  'mean_D<1' 'offset_abs>=0'
tsv_awk 'FNR > 1 {s = n("con_offset_frac") + n("con_contrast_frac") + n("con_shape_frac")
                 if (s < 1 - 1e-9 || s > 1 + 1e-9) {print "E_Con split sums to " s; exit 1}}' \
  "$out/control.tsv"
# Verdicts: two independent rows per pattern (decided by p) and one
# qualitative row for the figure.
tsv_awk 'NR > 1 && v("kind") == "independent" {i++}
         NR > 1 && v("kind") == "qualitative" {q++}
         END {if (i != 6 || q != 1) {print "verdicts: " i " independent, " q " qualitative"
                                     exit 1}}' \
  "$out/verdicts.tsv"
# Seams: 3 patterns' optimised tables on the domains [1, 2]^2 and [0, 1]^2
# (origin 1, 0), then w2 = 0, no propagation and the start tables on star
# (origin 1); ratios positive, outward components in [-1, 1]; the optimised
# border gradients (origin 1) point further outward than the start tables'.
"$expect" "$out/seams.tsv" rows=9 'tables==3' 'seam_ratio>1' 'seam_quarter>0' 'seam_other>0' \
  'seam_border>0' 'seam_octave1>0' 'seam_octave2>0' 'seam_octave4>0' 'border_outward>=-1' \
  'border_outward<=1'
tsv_awk 'NR > 1 && v("tables_from") == "optimised" && n("origin") == 1 {o[++no] = n("border_outward")}
         NR > 1 && v("tables_from") == "start table" {s = n("border_outward")}
         END {for (i = 1; i <= no; i++)
                if (!(o[i] > s)) {print "outward not above start"; exit 1}}' \
  "$out/seams.tsv"
# The verdicts' negative controls (baselines.tsv, two rows per pattern): the
# optimised tables against the pattern shuffled (|r| < 0.1, measured < 0.01
# at --quick) and the unoptimised start tables (worse than a flat image).
"$expect" "$out/baselines.tsv" rows=6 'n_random==99' 'r_pattern<0.1' 'r_pattern>-0.1'
tsv_awk 'NR > 1 && v("kind") != "qualitative" && v("control_verdict") == "-" {print "no control: " $0; exit 1}' \
  "$out/verdicts.tsv"
# The figures against their captions (tests/oracle_cheng.c): every panel
# recomputed from the run's tables.tsv through the noise's point call, and
# the pattern panels from the pattern PNGs, compared to 8 bits.
NL_PATTERNS="$pat" panels_oracle cheng c7 "$out" "$(dirname "$0")/../results/c7_terrain"

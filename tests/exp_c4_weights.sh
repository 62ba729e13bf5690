#!/usr/bin/env bash
# Quick C4: Table 4.1's six pairs (printed and swapped) and a weight sweep;
# bad input gives a one-line error and exit 2.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick "${NOIMG[@]}" --threads 2 --out "$out" --patterns "$pat" >/dev/null
# The seed runs are nl_parallel_for items (nl_study_cheng_runs): one thread
# gives the same tables, timing columns aside (the check ignores them).
same_on_one_thread "$exp" "$out" --patterns "$pat"
"$expect" "$out/table41.tsv" rows=6 'E_ks>0' 'E_ks<0.1' 'E_con>0' 'E_ks_swapped>0' 'E_ks_swapped<=E_ks' \
  'E_con_swapped>=E_con*0.95' image:textures.png
"$expect" "$out/table41_runs.tsv" rows=12 'seeds==3'
"$expect" "$out/sweep.tsv" rows=6 'E_ks>0' 'E_con>0' 'w1>0'
# the KS-dominated end of the sweep has the lower E_KS and the higher E_Con
awk -F'\t' 'NR==1{for(i=1;i<=NF;i++) col[$i]=i} NR==2{k=$col["E_ks"]; c=$col["E_con"]}
  END{if(!($col["E_ks"]<k && $col["E_con"]>c)){print "sweep ends not ordered"; exit 1}}' "$out/sweep.tsv"
bad() { refused "$exp" --quick --out "$out/bad" "$@"; }   # exit 2 and one line on stderr (tests/tsv.sh)
bad --patterns "$out/no-such-folder"
bad --patterns "$pat" --set w1=0 --set w2=0
bad --patterns "$pat" --set w1=-1
bad --patterns "$pat" --set f1=0
[ ! -e "$out/bad/table41.tsv" ]
# Readings of Table 4.1 over all six rows (printed, swapped, mixed_a_printed):
# permutation p in (0, 1]; the mixed reading's row (a) is the printed one's.
"$expect" "$out/readings.tsv" rows=3 'p_perm_ks>0' 'p_perm_ks<=1' 'rms_log_ks>0' 'r_log_ks>=-1' 'r_log_ks<=1'
tsv_awk 'NR > 1 {a[v("reading")] = n("E_ks_a")} END {if (a["mixed_a_printed"] != a["printed"] || a["swapped"] == a["printed"]) {print "row (a) per reading"; exit 1}}' "$out/readings.tsv"
# Grid sweep at --quick: grids 8 and 16 (64 and 256 points); E_Con per point
# measured 0.189 and 0.215 (seeds 1-3): bounds 0.1..0.3, and E_Con grows with the grid.
"$expect" "$out/grid_sweep.tsv" rows=2 'E_con_per_point>0.1' 'E_con_per_point<0.3' 'paper_E_con>49' 'paper_E_con<51'
tsv_awk 'NR > 2 && !(n("E_con") > prev) {print "E_con not growing with the grid"; exit 1} NR > 1 {prev = n("E_con")}' "$out/grid_sweep.tsv"
"$expect" "$out/reading_tests.tsv" rows=12 'p_welch>=0' 'p_welch<=1' 'seeds==3'

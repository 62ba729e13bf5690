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
# permutation p in (0, 1]; the mixed reading's row (a) is the printed one's;
# the uncentred rms of the log ratio (scale) is at least the centred one (shape).
"$expect" "$out/readings.tsv" rows=3 'p_perm_ks>0' 'p_perm_ks<=1' 'rms_log_ks>0' 'r_log_ks>=-1' 'r_log_ks<=1' \
  'rms_abs_log_ks>=rms_log_ks' 'rms_abs_log_con>=rms_log_con'
tsv_awk 'NR > 1 {a[v("reading")] = n("E_ks_a")} END {if (a["mixed_a_printed"] != a["printed"] || a["swapped"] == a["printed"]) {print "row (a) per reading"; exit 1}}' "$out/readings.tsv"
"$expect" "$out/reading_tests.tsv" rows=12 'p_welch>=0' 'p_welch<=1' 'seeds==3'
# E_Con at the printed pairs: grid 16 and the run's 64, budgets 1 and 0.1,
# three readings (12 rows) from 2 x 2 x 12 summary rows. E_Con per point
# measured 0.185..0.249 (seeds 1-3): bounds 0.1..0.3; E_Con grows with the
# grid for every budget and reading.
"$expect" "$out/econ_grid.tsv" rows=12 'E_con_per_point>0.1' 'E_con_per_point<0.3' \
  'paper_E_con>49' 'paper_E_con<51' 'E_con_lo<=E_con' 'E_con<=E_con_hi' 'budget>0' 'budget<=1' \
  'rms_abs_log_ks>0'
"$expect" "$out/econ_grid_runs.tsv" rows=48 'seeds==3'
tsv_awk 'NR > 1 {k = v("budget") "/" v("reading"); if (k in last && !(n("E_con") > last[k])) {print "E_con not growing with the grid: " k; exit 1} last[k] = n("E_con")}' "$out/econ_grid.tsv"
# Fig 4.8's printed panels' seams on the domains [1, 2]^2 and [0, 1]^2.
"$expect" "$out/seams_domain.tsv" rows=12 'tables==1' 'seam_ratio>1' 'seam_quarter>0' 'seam_border>0'
tsv_awk 'NR > 1 {c[n("origin")]++} END {if (c[1] != 6 || c[0] != 6) {print "seams_domain rows per origin"; exit 1}}' \
  "$out/seams_domain.tsv"
# Seams: the 12 panels and the unoptimised start tables, Welch p in [0, 1].
"$expect" "$out/seams.tsv" rows=13 'seam_ratio>1' 'seam_ratio<3'
"$expect" "$out/seam_tests.tsv" rows=12 'p_welch>=0' 'p_welch<=1' 'seeds==3'
"$expect" "$out/table41.tsv" 'seam_ratio>1' 'seam_ratio_swapped>1'
# Verdicts: E_KS printed (6, with the start tables as control: independent
# or by construction) and closest reading (6 selected 1/3), E_Con printed at
# the run's grid (6, controlled likewise) and at the fitted grid (1), the
# trend of r on log(w2 / w1) and (a) against (f), each with a control.
tsv_awk 'NR > 1 {c[v("kind")]++} NR > 1 && v("kind") ~ /^(independent|by construction)$/ && v("control_verdict") == "-" {print "no control: " $0; exit 1}
  END {if (NR != 22 || c["independent"] + c["by construction"] != 14 || c["selected 1/3"] != 6 || c["fitted 1/6"] != 1) {print "verdict kinds"; exit 1}}' "$out/verdicts.tsv"
"$expect" "$out/trend.tsv" rows=2 'points==6' 'rho>=-1' 'rho<=1' 'p_perm>0' 'p_perm<=1'
tsv_awk '$1 ~ /fitted/ && $2 !~ /^econ_grid.tsv:/ {print "fitted row source"; exit 1} $7 == "independent" && $8 ~ /consistent/ {print "independent row capped"; exit 1}' "$out/verdicts.tsv"
# The selected reading's panel (a) takes the column that reading gives it.
sel=$(tsv_awk 'NR > 1 && (best == "" || n("rms_abs_log_ks") < b) {b = n("rms_abs_log_ks"); best = v("reading")} END {print best}' "$out/readings.tsv")
want=$([ "$sel" = swapped ] && echo E_ks_swapped || echo E_ks)
tsv_awk -v want="table41.tsv:$want" 'v("quantity") == "E_KS, closest reading, panel a" && v("source") != want {print "panel (a) column " v("source"); exit 1}' "$out/verdicts.tsv"
# The figures against their captions (tests/oracle_cheng.c): every panel
# recomputed from the run's tables.tsv through the noise's point call, and
# the pattern panels from the pattern PNGs, compared to 8 bits.
NL_PATTERNS="$pat" panels_oracle cheng c4 "$out" "$(dirname "$0")/../results/c4_weights"
